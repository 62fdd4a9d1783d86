package org.rtcoord

import RTC.ExecutionContext
import org.rtcoord.internal.orFail

/** One execution context of a component, as that component knows it (by [handle]). */
public class ExecutionContextView internal constructor(
    /** The component through which the context was reached. */
    public val component: ComponentNode,
    /** The component's handle for the context. */
    public val handle: Int,
    private val context: ExecutionContext,
) {
    private val subject get() = "${component.path} context $handle"
    private val remote get() = component.core.remote

    /** The rate in Hz. */
    public suspend fun rate(): Double = remote.call(subject, "get_rate") { context.get_rate() }

    /** Sets the rate to [hz]. */
    public suspend fun setRate(hz: Double) {
        remote.call(subject, "set_rate") { context.set_rate(hz) }.orFail(subject, "set rate to $hz")
        component.refresh()
    }

    /** Whether the context is running. */
    public suspend fun isRunning(): Boolean = remote.call(subject, "is_running") { context.is_running() }

    /** Makes [participant] take part in this context. */
    public suspend fun add(participant: ComponentNode) {
        remote.call(subject, "add_component") { context.add_component(participant.component.ref) }.orFail(subject, "add ${participant.path}")
        participant.refresh()
        component.refresh()
    }

    /** Removes [participant] from this context. */
    public suspend fun remove(participant: ComponentNode) {
        remote.call(subject, "remove_component") { context.remove_component(participant.component.ref) }.orFail(subject, "remove ${participant.path}")
        participant.refresh()
        component.refresh()
    }
}
