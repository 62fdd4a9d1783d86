package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.default
import com.github.ajalt.clikt.parameters.types.choice
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode

/** `rtcoord mgr PATH list [WHAT]`: one kind of thing the manager has, one per line. */
class MgrListCommand(private val mgr: MgrCommand) : TreeCommand("list") {
    override fun help(context: Context): String =
        "List the components the manager and its slaves host (the default), the modules it can load, those it has loaded, or its factories."

    private val what by
        argument("WHAT", help = "components, modules (loadable), loaded or factories.")
            .choice("components", "modules", "loaded", "factories")
            .default("components")

    override suspend fun execute() {
        val manager = manager(mgr.path)
        val items =
            when (what) {
                "modules" -> manager.loadableModules().map(ManagerReport::moduleName)
                "loaded" -> manager.loadedModules().map(ManagerReport::moduleName)
                "factories" -> manager.factories().map(ManagerReport::factoryName)
                else -> hosted(manager).map { it.path.toString() }
            }
        if (session.json) echoJson(items) else items.forEach { echo(it) }
    }

    /** The components [manager] hosts, then those of its slaves, read afresh. */
    private suspend fun hosted(manager: ManagerNode): List<ComponentNode> {
        manager.refresh()
        val children = manager.children()
        return children.filterIsInstance<ComponentNode>() +
            children.filterIsInstance<ManagerNode>().flatMap { hosted(it) }
    }
}
