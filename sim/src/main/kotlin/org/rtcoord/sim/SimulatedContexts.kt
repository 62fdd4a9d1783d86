package org.rtcoord.sim

import org.rtcoord.profile.ProfileComponent
import org.rtcoord.runtime.ContextSpec

/**
 * The execution contexts a saved component owns, in its profile's order (handles 0, 1, ...): each with its kind
 * (`PERIODIC`, `EVENT_DRIVEN`, `OTHER`), rate and implementation ([ProfileKeys.CONTEXT_TYPE]). A profile that saves
 * none gives one periodic context at OpenRTM-aist's default rate; a rate or kind that cannot be simulated is replaced
 * by the default and named in [warnings].
 */
internal class SimulatedContexts(component: ProfileComponent, private val warnings: MutableList<String>) {
    val specs: List<ContextSpec> =
        component.executionContexts
            .sortedBy { it.id.toIntOrNull() ?: Int.MAX_VALUE }
            .map { context ->
                val where = "${component.instanceName} execution context ${context.id}"
                val kind =
                    ContextSpec.Kind.values().firstOrNull { it.name == context.kind.uppercase() }
                        ?: ContextSpec.Kind.PERIODIC.also {
                            warnings +=
                                "$where: kind '${context.kind}' is not PERIODIC, EVENT_DRIVEN or OTHER: simulated as PERIODIC"
                        }
                val rate =
                    context.rate?.takeIf { it > 0.0 && it.isFinite() }
                        ?: DEFAULT_RATE.also {
                            if (context.rate != null)
                                warnings +=
                                    "$where: rate ${context.rate} is not a positive number of Hz: simulated at $DEFAULT_RATE Hz"
                        }
                ContextSpec(rate, kind, context.ext.properties[ProfileKeys.CONTEXT_TYPE] ?: kind.defaultTypeName)
            }
            .ifEmpty { listOf(ContextSpec(DEFAULT_RATE)) }

    private companion object {
        /** OpenRTM-aist's default execution context rate (`exec_cxt.periodic.rate`), in Hz. */
        const val DEFAULT_RATE = 1000.0
    }
}
