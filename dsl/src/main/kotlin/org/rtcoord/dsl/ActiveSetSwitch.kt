package org.rtcoord.dsl

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.Node
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException

/**
 * Follows which configuration set is active in each component watched, as a coordinator means it: a switch from one set
 * to another. OpenRTM-aist's ConfigAdmin leaves no set active after every write until a set is activated again, so a
 * write shows as `default -> none -> default`: that is no switch, and `default -> none -> precise` is one, from
 * `default`.
 */
internal class ActiveSetSwitch : EventReading<ConfigurationSetActivated> {
    /** The set last seen active, by component path. */
    private val seen = ConcurrentHashMap<String, String>()

    override suspend fun prepare(node: Node): ConfigurationSetActivated? {
        if (node !is ComponentNode) return null
        try {
            node.configuration().activeSet?.let { seen[node.path.toString()] = it }
        } catch (e: RtcException) {
            // Measured from the first event instead.
        }
        return null
    }

    /** [event] as a switch from the set last active; null when no set became active or the same one did again. */
    override fun translate(event: RtcEvent): ConfigurationSetActivated? {
        if (event !is ConfigurationSetActivated) return null
        val now = event.new ?: return null
        val before = seen.put(event.source.path.toString(), now) ?: event.old
        return if (before != now) ConfigurationSetActivated(event.source, before, now) else null
    }
}
