package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/**
 * Test and coordinator files written into [directory] for a test of the runner, on the system simulated from the
 * examples' profile.
 */
internal class TestFolder(val directory: Path) {
    val examples: Path = Paths.get("../examples").toAbsolutePath().normalize()
    val system: Path = examples.resolve("localisation.xml")

    /** Writes [text] to [name] (below [directory]) and returns it. */
    fun write(name: String, text: String): Path =
        directory.resolve(name).also {
            Files.createDirectories(it.parent)
            Files.writeString(it, text.trimIndent() + "\n")
        }

    /** A test file [name] on the examples' system running [coordinator], its body [steps]. */
    fun test(name: String, coordinator: String, steps: String): Path =
        write(name, "system(\"$system\")\ncoordinator(\"$coordinator\")\n" + steps.trimIndent())
}
