package org.rtcoord

/**
 * The tree's model of the live system at one point of its history: every event up to [sequence] is in it, none after.
 * Taken without a remote call by [RtcTree.snapshot]; a subscription made before it gets every event after it
 * ([RtcEvent.sequence] greater than [sequence]), which [RtcTree.follow] hands over in one step.
 *
 * It holds what the tree knows: the nodes its listings found (each component once, at its
 * [ComponentNode.canonicalPath]), their states as the tree's events last told them (as last read for a component nobody
 * watches), and what it cannot know: name servers that do not answer, managers found dead. Only the tree makes one, as
 * it makes its entries: these classes are sealed for the reason [Node] gives.
 */
public sealed class SystemSnapshot(
    /** The number of the last event this snapshot holds. */
    public val sequence: Long,
    /** Every component the tree's listings found, once each, in the order they were found. */
    public val components: List<ComponentEntry>,
    /** The tree's name servers, each with whether it answers. */
    public val nameServers: List<NameServerEntry>,
    /** The managers found dead and not answering again since, each as the event that said so. */
    public val managerOutages: List<ManagerDied>,
) {
    /** The managers found dead and not answering again since. */
    public val deadManagers: List<ManagerNode>
        get() = managerOutages.map { it.source }

    /** The entry of [node]'s component, wherever it was found; null if the tree has not found it. */
    public fun component(node: ComponentNode): ComponentEntry? = components.firstOrNull {
        it.node.isSameComponent(node)
    }

    override fun toString(): String =
        "SystemSnapshot(sequence=$sequence, ${components.size} components, ${nameServers.size} name servers)"
}

/**
 * One component in a [SystemSnapshot]: its [node] at its canonical path, its [states] by execution context handle as
 * the tree's events last told them, and how it is watched. [alive] is false for a component found dead or unreachable;
 * its states are then the last ones known.
 */
public sealed class ComponentEntry(
    /** The component, at its canonical path. */
    public val node: ComponentNode,
    /** Its lifecycle state in each execution context, by handle; empty before it was first read. */
    public val states: Map<Int, LifeCycle>,
    /** Whether it answered when last asked. */
    public val alive: Boolean,
    /** How the tree watches it; null when nobody watches it. */
    public val watchMethod: WatchMethod?,
    /**
     * Its FSM's state as its events last told it, or why that is not known; null for a component not known to have an
     * FSM: one that neither offers FSM4RTC's `ExtendedFsmService` nor told an FSM state, or whose profile was never
     * read.
     */
    public val fsm: FsmStatus?,
) {
    /** Its canonical path. */
    public val path: RtcPath
        get() = node.path

    /** Every path the tree found it at, its canonical path among them: a manager's listing is an alias. */
    public val paths: List<RtcPath>
        get() = node.component.knownPaths

    /** Whether it is [path] or below it, at any of its [paths]. */
    public fun isAtOrBelow(path: RtcPath): Boolean = paths.any { it.startsWith(path) }

    /** The state in the context with handle 0 (or the first one), as tools show it; UNKNOWN before a read. */
    public val state: LifeCycle
        get() = states[0] ?: states.entries.minByOrNull { it.key }?.value ?: LifeCycle.UNKNOWN

    /** The state over all its execution contexts, as rtls merges it (see [ComponentSummary.overallState]). */
    public val overallState: LifeCycle
        get() = ComponentSummary(states, emptyList()).overallState

    override fun toString(): String = "$path ${if (alive) state else "unreachable"}"
}

/**
 * A name server in a [SystemSnapshot]; [lostSince] (milliseconds since the epoch) and [cause] are set while it does not
 * answer.
 */
public sealed class NameServerEntry(
    /** The name server. */
    public val node: NameServerNode,
    /** Since when it has not answered; null while it answers (or was never asked). */
    public val lostSince: Long?,
    /** Why it does not answer; null while it answers. */
    public val cause: RtcException?,
) {
    /** Whether it answered when last asked. */
    public val reachable: Boolean
        get() = lostSince == null

    override fun toString(): String = "${node.path} ${if (reachable) "reachable" else "unreachable: ${cause?.reason}"}"
}

/** The [SystemSnapshot]s the tree makes. */
internal class SystemSnapshotImpl(
    sequence: Long,
    components: List<ComponentEntry>,
    nameServers: List<NameServerEntry>,
    managerOutages: List<ManagerDied>,
) : SystemSnapshot(sequence, components, nameServers, managerOutages)

/** The [ComponentEntry]s the tree makes. */
internal class ComponentEntryImpl(
    node: ComponentNode,
    states: Map<Int, LifeCycle>,
    alive: Boolean,
    watchMethod: WatchMethod?,
    fsm: FsmStatus?,
) : ComponentEntry(node, states, alive, watchMethod, fsm)

/** The [NameServerEntry]s the tree makes. */
internal class NameServerEntryImpl(node: NameServerNode, lostSince: Long?, cause: RtcException?) :
    NameServerEntry(node, lostSince, cause)
