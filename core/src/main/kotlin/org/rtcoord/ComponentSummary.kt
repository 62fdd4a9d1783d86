package org.rtcoord

/**
 * What a listing shows of a component (`rtls -l`): its state in each of its execution contexts and its
 * ports with their connectors. [ComponentNode.refreshSummary] reads it in fewer calls than a whole
 * [ComponentSnapshot] (nothing about the execution contexts themselves: two calls fewer for each);
 * every full read brings it up to date as well.
 */
public data class ComponentSummary(
    /** The component's state in each execution context, by its handle for the context (owned ones first). */
    val states: Map<Int, LifeCycle>,
    val ports: List<PortSnapshot>,
)

/** The summary of what this snapshot holds. */
public val ComponentSnapshot.summary: ComponentSummary
    get() = ComponentSummary(contexts.associate { it.handle to it.state }, ports)
