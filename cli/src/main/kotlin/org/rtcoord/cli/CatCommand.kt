package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.encodeToJsonElement
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode
import org.rtcoord.WrongKindException
import org.rtcoord.ZombieNode
import org.rtcoord.cli.json.PrettyJson

/** `rtcoord cat`: rtcat for components, ports and managers. */
class CatCommand : TreeCommand("cat") {
    override fun help(context: Context): String =
        "Show a component (profile, execution contexts, ports and their connections), one of its ports (PATH:PORT), " +
            "or a manager (profile, modules, factories)."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord cat /localhost/host.host_cxt/laser0.rtc" to "the laser's state, contexts and ports",
            "rtcoord cat -l /localhost/host.host_cxt/laser0.rtc:laser" to "one port with its connectors' properties",
            "rtcoord cat /localhost/host.host_cxt/manager.mgr" to "what the manager has loaded and can create",
        )

    private val long by option("-l", help = "Also properties, connector details and configuration sets.").flag()

    private val paths by
        argument("PATH", help = "Components (name.rtc), ports (name.rtc:port) or managers (name.mgr).")
            .multiple(required = true)

    override suspend fun execute() {
        // Everything is read before anything is printed: an error leaves no half-printed report.
        val reports = paths.map { report(it) }
        if (session.json) {
            echoJson(reports.map { it.json() })
            return
        }
        reports.forEachIndexed { index, report ->
            if (index > 0) echo()
            report.lines().forEach { echo(it) }
        }
    }

    private suspend fun report(text: String): Report {
        val path = pathOf(text)
        if (path.port != null) {
            val port = PortReport.read(port(text))
            return Report({ port.lines(long, "") }, { PrettyJson.encodeToJsonElement(port.toJson(path.toString())) })
        }
        return when (val node = node(text)) {
            is ComponentNode ->
                ComponentReport.read(tree, node, withConfiguration = long).let { report ->
                    Report({ report.lines(long) }, { PrettyJson.encodeToJsonElement(report.toJson()) })
                }
            is ManagerNode ->
                ManagerReport.read(node).let { report ->
                    Report({ report.lines(long) }, { PrettyJson.encodeToJsonElement(report.toJson()) })
                }
            is ZombieNode -> throw node.cause
            else -> throw WrongKindException(node.path.toString(), "component, port or manager", node.kind.label)
        }
    }

    /** One PATH's report, as text or JSON (a component's, a port's or a manager's). */
    private class Report(val lines: () -> List<String>, val json: () -> JsonElement)
}
