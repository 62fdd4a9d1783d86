package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * What a listing shows of a component (`rtls -l`): its state in each of its execution contexts and its ports with their
 * connectors. [ComponentNode.refreshSummary] reads it in fewer calls than a whole [ComponentSnapshot] (nothing about
 * the execution contexts themselves: two calls fewer for each); every full read brings it up to date as well.
 */
public class ComponentSummary(
    /** The component's state in each execution context, by its handle for the context (owned ones first). */
    public val states: Map<Int, LifeCycle>,
    public val ports: List<PortSnapshot>,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("states" to states, "ports" to ports)

    /**
     * The component's state over all its execution contexts, as rtctree merges it for rtls: ERROR over ACTIVE over
     * INACTIVE, else CREATED; UNKNOWN only without any context.
     */
    public val overallState: LifeCycle
        get() {
            if (states.isEmpty()) return LifeCycle.UNKNOWN
            return listOf(LifeCycle.ERROR, LifeCycle.ACTIVE, LifeCycle.INACTIVE).firstOrNull { it in states.values }
                ?: LifeCycle.CREATED
        }
}

/** The summary of what this snapshot holds. */
public val ComponentSnapshot.summary: ComponentSummary
    // A list's toMap() makes a map of one entry, a fifth of a hash map's weight, for the common component of one
    // context.
    get() = ComponentSummary(contexts.map { it.handle to it.state }.toMap(), ports)
