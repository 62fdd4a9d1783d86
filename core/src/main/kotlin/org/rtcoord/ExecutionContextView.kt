package org.rtcoord

import org.rtcoord.internal.ContextCalls

/**
 * One execution context of a component, as that component knows it (by [handle]): [ComponentNode.executionContext]
 * gives it. The class is sealed for the reason [Node] gives.
 */
public sealed class ExecutionContextView(
    /** The component through which the context was reached. */
    public val component: ComponentNode,
    /** The component's handle for the context. */
    public val handle: Int,
    private val calls: ContextCalls,
) {
    /** The rate in Hz. */
    @JvmSynthetic public suspend fun rate(): Double = calls.rate()

    /** Sets the rate to [hz]. */
    @JvmSynthetic
    public suspend fun setRate(hz: Double) {
        calls.setRate(hz)
        component.refresh()
    }

    /** Whether the context is running. */
    @JvmSynthetic public suspend fun isRunning(): Boolean = calls.isRunning()

    /** Makes [participant] take part in this context. */
    @JvmSynthetic
    public suspend fun add(participant: ComponentNode) {
        calls.add(participant.component, participant.path.toString())
        participant.refresh()
        component.refresh()
    }

    /** Removes [participant] from this context. */
    @JvmSynthetic
    public suspend fun remove(participant: ComponentNode) {
        calls.remove(participant.component, participant.path.toString())
        participant.refresh()
        component.refresh()
    }
}

/** The [ExecutionContextView]s a component gives. */
internal class ExecutionContextViewImpl(component: ComponentNode, handle: Int, calls: ContextCalls) :
    ExecutionContextView(component, handle, calls)
