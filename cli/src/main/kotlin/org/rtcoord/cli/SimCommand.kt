package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.path
import org.rtcoord.RtcPath
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.sim.SimConsole
import org.rtcoord.sim.SimulatedSystem
import org.rtcoord.sim.SimulationComparison

/**
 * `rtcoord sim SYSTEM.xml`: the system a profile describes, simulated in this process on a naming service of its own,
 * with faults typed on stdin, until stdin closes; with `--compare PATH`, compared with the live system it was saved
 * from instead.
 */
class SimCommand : TreeCommand("sim") {
    override fun help(context: Context): String =
        "Simulate the RT system an RTSProfile describes (as `rtcoord profile save` writes it): its components with their ports " +
            "(every OpenRTM-aist data type, and the system's own types with --idl) and interfaces, configuration sets and " +
            "execution contexts, connected and active, and its managers (the master, each slave in a process of its own with " +
            "the components it hosts), on a naming service of its own. What cannot be simulated is said on stderr, one line " +
            "each, and left out. Prints the naming service's address, then takes faults on stdin, one a line, each answered " +
            "with a line, until stdin closes: the commands are listed below. With --compare, compares the simulation with " +
            "the live system the profile was saved from, one line per difference, and exits: 0 when there is none, 1 when " +
            "there are."

    // In the epilog, which is printed as written: one command a line.
    override fun helpEpilog(context: Context): String =
        SimConsole.HELP +
            "\n\n" +
            examples(
                "rtcoord sim examples/localisation.xml" to
                    "simulate the paper's system; the first line says where its naming service is",
                "rtcoord -n 127.0.0.1:PORT run examples/localisation.coord.kts" to
                    "then, in another shell, run a coordinator on it",
                "echo 'break laser0' | rtcoord sim --port 2809 nav.xml" to
                    "a simulated system on the usual naming port, its laser broken",
                "rtcoord sim --idl idl/ robot.xml" to
                    "a system whose ports carry types of its own, declared by the IDL in idl/",
                "echo 'kill-manager sensors' | rtcoord sim robot.xml" to
                    "the slave manager sensors dies with the components it hosts",
                "rtcoord sim --compare /robot:2809 robot.xml" to
                    "how the simulation of robot.xml differs from the robot it was saved from",
            )

    private val profile by
        argument("SYSTEM", help = "The RTSProfile (XML or YAML).").path(mustExist = true, canBeDir = false)

    private val host by
        option("--host", metavar = "ADDRESS", help = "The address the naming service and every component listen on.")
            .default("127.0.0.1")

    private val port by
        option("--port", metavar = "PORT", help = "The naming service's port; by default a free one.").int().default(0)

    private val idl by
        option(
                "--idl",
                metavar = "DIR",
                help =
                    "A directory of IDL files declaring the system's own data types (besides OpenRTM-aist's, which are known); " +
                        "they may #include \"BasicDataType.idl\" and the like. Repeat for several directories.",
            )
            .path(mustExist = false, canBeFile = false)
            .multiple()

    private val compare by
        option(
            "--compare",
            metavar = "PATH",
            help =
                "Compare the simulation with the live system at PATH (/HOST:PORT, or a naming context below it) and exit: " +
                    "components, ports, interfaces, connections, contexts, configuration sets and managers.",
        )

    override suspend fun execute() {
        val system =
            try {
                SimulatedSystem.start(profile, host, port, idl)
            } catch (e: ProfileFormatException) {
                fail(e.message.orEmpty(), e)
            } catch (e: IllegalArgumentException) {
                fail("$profile: ${e.message}", e)
            }
        system.use {
            (system.warnings + system.notes).forEach { echo("rtcoord sim: $profile: $it", err = true) }
            val live = compare
            if (live != null) return compare(system, pathOf(live))
            echo("naming ${system.address}")
            echo("try rtcoord -n ${system.address} ls -l -R")
            echo("try rtls -l -R /${system.address}/${RuntimeProcess.hostContext}")
            echo("ready ${system.components.size} components")
            val console = SimConsole(system, System.out, System.err)
            System.`in`.bufferedReader().forEachLine(console::execute)
        }
    }

    private suspend fun compare(system: SimulatedSystem, live: RtcPath) {
        val comparison = SimulationComparison.of(tree, live, system)
        comparison.differences.forEach { echo(it) }
        val count = comparison.differences.size
        if (count > 0)
            fail(
                "$profile: $count difference${if (count == 1) "" else "s"} from $live (${comparison.compared} compared)"
            )
        echo("no difference from $live: ${comparison.compared} compared")
    }
}
