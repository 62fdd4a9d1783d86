package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import java.io.File
import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/** `rtcoord graph`: rtstodot for the running system rather than a saved profile. */
class GraphCommand : TreeCommand("graph") {
    override fun help(context: Context): String =
        "Print the component network below PATH as a Graphviz DOT graph: components coloured by state, data " +
            "connections as arrows from out-port to in-port. With --svg, have Graphviz's dot draw it into a file."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord graph /localhost/host.host_cxt | dot -Tpng > system.png" to "draw it with dot yourself",
            "rtcoord graph /localhost --svg system.svg" to "let rtcoord run dot",
        )

    private val path by argument("PATH", help = "A name server, context, manager or component.")

    private val svg by
        option("--svg", metavar = "FILE", help = "Write SVG to FILE with Graphviz's dot instead of printing DOT.")
            .path(canBeDir = false)

    override suspend fun execute() {
        val top = node(path)
        discover(top, progressLine())
        val dot = ComponentNetwork(top).graph().render()
        val file = svg
        if (file == null) echo(dot, trailingNewline = false) else draw(dot, file)
    }

    /** Runs `dot -Tsvg` on [dot], writing [file]. */
    private fun draw(dot: String, file: Path) {
        val executable =
            onPath("dot") ?: fail("dot: not found on PATH: install Graphviz for --svg, or leave --svg out to print DOT")
        val process =
            ProcessBuilder(executable.toString(), "-Tsvg", "-o", file.toString()).redirectErrorStream(true).start()
        try {
            process.outputStream.use { it.write(dot.toByteArray()) }
        } catch (e: IOException) {
            // dot quit before reading everything; what it printed says why.
        }
        val said = process.inputStream.bufferedReader().readText()
        if (process.waitFor() != 0)
            fail("dot: ${said.lines().firstOrNull { it.isNotBlank() } ?: "exit status ${process.exitValue()}"}")
    }

    /** The executable [name] in a directory of the PATH variable (read through Clikt, so tests can set it). */
    private fun onPath(name: String): Path? =
        currentContext
            .readEnvvar("PATH")
            .orEmpty()
            .split(File.pathSeparatorChar)
            .filter { it.isNotEmpty() }
            .map { Paths.get(it, name) }
            .firstOrNull { Files.isExecutable(it) }
}
