package org.rtcoord.sim

import org.rtcoord.runtime.FaultConsole
import java.io.PrintStream

/**
 * The faults `rtcoord sim` takes on stdin, one a line: the fixtures' (`fail`, `break`, `repair`, `freeze`,
 * `hang`, `exit`, `activate`), and `kill-manager` and `restart-naming` on the whole [system]. Each is
 * answered with one line on [out], each mistake with one line on [err].
 */
public class SimConsole(private val system: SimulatedSystem, private val out: PrintStream, private val err: PrintStream) {
    private val components = FaultConsole({ system.components }, out, err, tool = "rtcoord sim")

    /** Acts on one line of input. */
    public fun execute(line: String) {
        val words = line.trim().split(Regex("\\s+")).filter { it.isNotEmpty() }
        when (words.firstOrNull()) {
            "help" -> say(HELP)
            "kill-manager" -> try {
                system.killManager()
                say("killed the manager: it no longer answers and its name stays bound, as a killed rtcd leaves it")
            } catch (e: IllegalStateException) {
                complain("kill-manager: ${e.message}")
            }
            "restart-naming" -> {
                system.restartNaming()
                say("restarted the naming service at ${system.address}, with its bindings, as omniNames from its log")
            }
            else -> components.execute(line)
        }
    }

    private fun say(text: String) {
        out.println(text)
        out.flush()
    }

    private fun complain(text: String) {
        err.println("rtcoord sim: $text")
        err.flush()
    }

    public companion object {
        /** What `help` prints. */
        public val HELP: String = FaultConsole.HELP.substringBeforeLast("\n") + "\n" + """
              kill-manager    the master manager's process dies (kill -9): its name stays bound, nothing can be created
              restart-naming  the naming service stops and starts again on its port, with its bindings
              help            this list
        """.trimIndent().prependIndent("  ")
    }
}
