package org.rtcoord.dsl

import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ParameterChanged
import org.rtcoord.RtcEvent

/**
 * [event] as a change of the effective value of a parameter, the value in the active configuration set
 * (the component as last read tells which one that is): a change in the active set as it is; a switch
 * of the active set as a change of each parameter whose value differs between the two sets, named after
 * the set now active. Only [parameter] is considered. Null when the effective value did not change.
 */
internal fun effectiveChange(event: RtcEvent, parameter: String): ParameterChanged? = when (event) {
    is ParameterChanged -> event.takeIf { it.set == event.source.snapshots.value?.configuration?.activeSet }
    is ConfigurationSetActivated -> event.source.snapshots.value?.configuration?.sets?.let { sets ->
        val old = sets[event.old]?.get(parameter)
        val new = sets[event.new]?.get(parameter)
        if (old != new) ParameterChanged(event.source, event.new, parameter, old, new) else null
    }
    else -> null
}
