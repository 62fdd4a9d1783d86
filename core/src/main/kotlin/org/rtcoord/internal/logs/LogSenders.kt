package org.rtcoord.internal.logs

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.internal.componentsListed

/**
 * Who sent a log record, found in what the tree's listings hold now, without a remote call.
 *
 * OpenRTM-aist's C++ names a component's logger by its instance name (`RTObject_impl::setInstanceName`); its Python
 * names every component's logger `rtobject` and FluentLogger prefixes it with `fluent.`, so for Python only the manager
 * tells, and a manager that hosts one component (the usual standalone component's process) stands for it: its node,
 * where the tree lists one, else the one component whose profile names it (a Python manager that is no master is in no
 * naming context). Answers are kept for [ttlMillis], so that a flood of records does not walk the listings for each.
 */
internal class LogSenders(
    private val tops: () -> List<Node>,
    private val now: () -> Long,
    private val ttlMillis: Long = 1_000,
) {
    private class Found(val node: Node?, val at: Long)

    /** Read without a lock: every record looks its sender up here. */
    private val found = ConcurrentHashMap<Pair<String, String?>, Found>()

    /** Forgets every answer: the listings changed. */
    fun forget() {
        found.clear()
    }

    /** The component or manager [logger] of manager [manager] is, or null when no listed one matches. */
    fun senderOf(logger: String, manager: String?): Node? {
        val key = logger to manager
        val time = now()
        found[key]
            ?.takeIf { time - it.at < ttlMillis }
            ?.let {
                return it.node
            }
        val node = find(logger.removePrefix(PYTHON_PREFIX), manager)
        if (found.size >= MAX_KEPT) found.clear()
        found[key] = Found(node, time)
        return node
    }

    private fun find(name: String, manager: String?): Node? {
        val components = componentsListed(tops())
        val named = components.filter { it.name.removeSuffix(COMPONENT_KIND) == name }
        val ofManager = named.filter { component -> component.hostingManagers().any { it.named(manager) } }
        (ofManager.singleOrNull() ?: named.singleOrNull())?.let {
            return it
        }
        if (manager == null) return null
        val host = components.asSequence().flatMap { it.hostingManagers() }.firstOrNull { it.named(manager) }
        // A Python manager that is not a master binds itself nowhere: a standalone component's process shows no
        // manager node, only its components, whose profiles say their manager's name (OpenRTM's Manager passes
        // `manager.instance_name` on to each component it creates).
        val elsewhere = components.filter { component ->
            component.profileManager() == manager &&
                (host == null || component.hostingManagers().none { it.path == host.path })
        }
        if (host == null) return elsewhere.singleOrNull()
        // Two managers of that name, one the tree lists and one it does not (every Python manager is `manager`
        // unless told otherwise): the record could be from either.
        if (elsewhere.isNotEmpty()) return null
        return components.singleOrNull { component -> component.hostingManagers().any { it.path == host.path } } ?: host
    }

    /** The name of the manager that created this component, as its profile read last says; null before a read. */
    private fun ComponentNode.profileManager(): String? = component.snapshot.value?.properties?.get(MANAGER_PROPERTY)

    private fun ComponentNode.hostingManagers(): Collection<ManagerNode> = component.hostingManagers

    private fun ManagerNode.named(manager: String?) = manager != null && name.removeSuffix(MANAGER_KIND) == manager

    private companion object {
        const val PYTHON_PREFIX = "fluent."
        const val COMPONENT_KIND = ".rtc"
        const val MANAGER_KIND = ".mgr"
        const val MANAGER_PROPERTY = "manager.instance_name"
        /** More distinct senders than any system has: a sender naming a new logger at every record cannot grow it. */
        const val MAX_KEPT = 4096
    }
}
