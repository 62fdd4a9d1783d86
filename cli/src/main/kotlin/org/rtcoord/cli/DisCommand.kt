package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.optional
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.NotFoundException

/** `rtcoord dis`: rtdis, by far port, by connector id or for the whole port. */
class DisCommand : TreeCommand("dis") {
    override fun help(context: Context): String =
        "Disconnect a port: from the second port when one is given, or only connector --id, or else every connection of the port."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord dis /localhost/host.host_cxt/laser0.rtc:laser /localhost/host.host_cxt/laser_localise0.rtc:laser" to
                "the connection between two ports",
            "rtcoord dis /localhost/host.host_cxt/laser0.rtc:laser --id 9a1c0e" to "one connector",
            "rtcoord dis /localhost/host.host_cxt/laser0.rtc:laser" to "everything connected to the laser port",
        )

    private val from by argument("PATH:PORT", help = "The port to disconnect.")

    private val to by argument("PATH:PORT", help = "Only connectors to this port.").optional()

    private val id by option("--id", metavar = "ID", help = "Only the connector with this id.")

    override suspend fun execute() {
        val port = port(from)
        val connectors = port.snapshot().connectors.map { it.id }
        val doomed =
            when {
                to != null -> {
                    val other = port(to!!)
                    val between = port.connectorsTo(other).map { it.id }
                    if (between.isEmpty())
                        throw NotFoundException(port.path.toString(), "not connected to ${other.path}")
                    between
                        .filter { id == null || it == id }
                        .ifEmpty {
                            throw NotFoundException(
                                port.path.toString(),
                                "connector '$id' does not lead to ${other.path}",
                            )
                        }
                }
                id != null ->
                    listOf(id!!)
                        .filter { it in connectors }
                        .ifEmpty {
                            throw NotFoundException(
                                port.path.toString(),
                                "no connector '$id' (connectors: ${connectors.joinToString().ifEmpty { "none" }})",
                            )
                        }
                else -> connectors
            }
        eachInTurn(doomed, "disconnected", { "connector '$it'" }) { port.disconnect(it) }
    }
}
