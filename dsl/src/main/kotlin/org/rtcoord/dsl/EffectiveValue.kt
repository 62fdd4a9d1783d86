package org.rtcoord.dsl

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.Node
import org.rtcoord.ParameterChanged
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException

/**
 * Follows the effective value of [parameter], its value in the active configuration set, in each component watched: a
 * change in the active set and a switch to a set that holds another value both change it. Judged from the component as
 * last read, so two changes read at once (values set in a set, then that set activated) are one change. Each event must
 * be shown once, in order.
 */
internal class EffectiveValue(private val parameter: String) : EventReading<ParameterChanged> {
    /** A value as last seen; [value] null: the active set does not hold the parameter. */
    private class Seen(val value: String?)

    private val seen = ConcurrentHashMap<String, Seen>()

    override suspend fun prepare(node: Node): ParameterChanged? {
        if (node !is ComponentNode) return null
        try {
            val configuration = node.configuration()
            seen[node.path.toString()] = Seen(configuration.sets[configuration.activeSet]?.get(parameter))
        } catch (e: RtcException) {
            // Measured from the first event instead.
        }
        return null
    }

    /**
     * [event] as a change of the effective value, named after the set now active; null when the value did not change.
     */
    override fun translate(event: RtcEvent): ParameterChanged? {
        if (!(event is ParameterChanged && event.name == parameter) && event !is ConfigurationSetActivated) return null
        val source = event.source as? ComponentNode ?: return null
        val configuration = source.snapshots.value?.configuration ?: return null
        // With no set active (after a write, until one is activated) the component keeps the values it had.
        val active = configuration.activeSet ?: return null
        val now = configuration.sets[active]?.get(parameter)
        val before =
            seen.put(source.path.toString(), Seen(now))?.value
                ?: when (event) {
                    is ParameterChanged -> if (event.set == active) event.old else now
                    is ConfigurationSetActivated -> configuration.sets[event.old]?.get(parameter)
                    else -> now
                }
        return if (before != now) ParameterChanged(source, active, parameter, before, now) else null
    }
}
