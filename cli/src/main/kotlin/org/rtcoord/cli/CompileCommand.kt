package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import java.nio.file.Path
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/**
 * Compiles a coordinator script ahead of time into a jar that runs without the Kotlin compiler: from Java and inside an
 * Eclipse plug-in (`JavaCoordinator.load(tree, jar)` through the OSGi bundle), or with `rtcoord run NAME.jar`. Only the
 * rtcoord version that compiled it loads it. Touches no system.
 */
class CompileCommand : TreeCommand("compile") {
    override fun help(context: Context): String =
        "Compile a coordinator (SCRIPT.coord.kts) into a jar that runs without the Kotlin compiler: with rtcoord run, " +
            "from Java, or in an Eclipse plug-in through the OSGi bundle. Only this rtcoord version (${CompiledCoordinator.version}) loads it."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord compile examples/localisation.coord.kts -o localisation.jar" to
                "the paper's coordinator, compiled",
            "rtcoord -n localhost run localisation.jar" to "run it, as the script would run",
        )

    private val script by argument("SCRIPT", help = "The coordinator script.").path()
    private val output by
        option(
                "-o",
                "--output",
                metavar = "JAR",
                help = "The jar to write (default: the script's name, .jar instead of .coord.kts).",
            )
            .path()

    override suspend fun execute() {
        CompilerJars.require("rtcoord compile")
        val jar = output ?: defaultJar(script)
        try {
            ScriptHost().compile(script, jar)
        } catch (e: ScriptFailure) {
            // Each problem (file:line:col: message) is an error line of its own.
            e.problems.dropLast(1).forEach { echo("rtcoord: $it", err = true) }
            fail(e.problems.last(), e)
        }
        confirm("$script: compiled into $jar")
    }

    private fun defaultJar(script: Path): Path =
        script.resolveSibling(script.fileName.toString().removeSuffix(".kts").removeSuffix(".coord") + ".jar")
}
