package org.rtcoord.sim

import java.io.PrintStream
import org.rtcoord.runtime.FaultConsole

/**
 * The faults `rtcoord sim` takes on stdin, one a line: the fixtures' (`fail`, `break`, `repair`, `freeze`, `hang`,
 * `lose-connectors`, `exit`, `activate`), `kill-manager [NAME]` and `restart-naming` on the whole [system]. Each is
 * answered with one line on [out], each mistake with one line on [err].
 */
public class SimConsole(
    private val system: SimulatedSystem,
    private val out: PrintStream,
    private val err: PrintStream,
) {
    private val components = FaultConsole({ system.components }, out, err, tool = "rtcoord sim")

    /** Acts on one line of input. */
    public fun execute(line: String) {
        val words = line.trim().split(Regex("\\s+")).filter { it.isNotEmpty() }
        when (words.firstOrNull()) {
            "help" -> say(HELP)
            "kill-manager" ->
                try {
                    val name = words.getOrNull(1)
                    if (name == null) system.killManager() else system.killManager(name)
                    say(
                        "killed the manager${name?.let { " $it" }.orEmpty()}: it no longer answers, nor do the components it hosted, " +
                            "and their names stay bound, as a killed rtcd leaves them"
                    )
                } catch (e: IllegalStateException) {
                    complain("kill-manager: ${e.message}")
                } catch (e: IllegalArgumentException) {
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
        public val HELP: String =
            FaultConsole.HELP.substringBeforeLast("\n") +
                "\n" +
                """
                kill-manager [NAME]
                                the process of manager NAME dies (kill -9) with every component it hosts, their names
                                left bound: a slave (localisation, manager.mgr/localisation) or, without NAME, the master
                restart-naming  the naming service stops and starts again on its port, with its bindings
                help            this list
                """
                    .trimIndent()
                    .prependIndent("  ")
    }
}
