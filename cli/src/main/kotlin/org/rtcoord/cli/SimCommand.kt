package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.path
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.sim.SimConsole
import org.rtcoord.sim.SimulatedSystem

/**
 * `rtcoord sim SYSTEM.xml`: the system a profile describes, simulated in this process on a naming
 * service of its own, with faults typed on stdin, until stdin closes.
 */
class SimCommand : CliktCommand("sim") {
    override fun help(context: Context): String =
        "Simulate the RT system an RTSProfile describes (as `rtcoord profile save` writes it): its components with their ports, " +
            "configuration sets and execution context rates, connected and active, and its manager, on a naming service of " +
            "its own. Prints the naming service's address, then takes faults on stdin, one a line, each answered with a " +
            "line, until stdin closes: the commands are listed below."

    // In the epilog, which is printed as written: one command a line.
    override fun helpEpilog(context: Context): String = SimConsole.HELP + "\n\n" + examples(
        "rtcoord sim examples/localisation.xml" to "simulate the paper's system; the first line says where its naming service is",
        "rtcoord -n 127.0.0.1:PORT run examples/localisation.coord.kts" to "then, in another shell, run a coordinator on it",
        "echo 'break laser0' | rtcoord sim --port 2809 nav.xml" to "a simulated system on the usual naming port, its laser broken",
        "rtcoord sim --idl idl/ robot.xml" to "a system whose ports carry types of its own, declared by the IDL in idl/",
    )

    private val profile by argument("SYSTEM", help = "The RTSProfile (XML or YAML).").path(mustExist = true, canBeDir = false)

    private val host by option("--host", metavar = "ADDRESS", help = "The address the naming service and every component listen on.")
        .default("127.0.0.1")

    private val port by option("--port", metavar = "PORT", help = "The naming service's port; by default a free one.").int().default(0)

    private val idl by option(
        "--idl", metavar = "DIR",
        help = "A directory of IDL files declaring the system's own data types (besides OpenRTM-aist's, which are known); " +
            "they may #include \"BasicDataType.idl\" and the like. Repeat for several directories.",
    ).path(mustExist = false, canBeFile = false).multiple()

    override fun run() {
        val system = try {
            SimulatedSystem.start(profile, host, port, idl)
        } catch (e: ProfileFormatException) {
            throw CommandFailed(e.message.orEmpty())
        } catch (e: IllegalArgumentException) {
            throw CommandFailed("$profile: ${e.message}")
        }
        system.use {
            system.warnings.forEach { echo("rtcoord sim: $profile: $it", err = true) }
            echo("naming ${system.address}")
            echo("try rtcoord -n ${system.address} ls -l -R")
            echo("try rtls -l -R /${system.address}/${RuntimeProcess.hostContext}")
            echo("ready ${system.components.size} components")
            val console = SimConsole(system, System.out, System.err)
            System.`in`.bufferedReader().forEachLine(console::execute)
        }
    }
}
