package org.rtcoord

import org.rtcoord.internal.TreeCore

/** What a node of the tree stands for. */
public enum class NodeKind {
    ROOT,
    NAME_SERVER,
    CONTEXT,
    COMPONENT,
    MANAGER,
    ZOMBIE,
    UNKNOWN;

    /** The kind in words, for messages: `component`, `name server`, `zombie`... */
    public val label: String
        get() = name.lowercase().replace('_', ' ')
}

/**
 * A node of an [RtcTree]: the root, a name server, a naming context, a component, a manager, a dead registration
 * ([ZombieNode]) or an object of another type ([UnknownNode]).
 *
 * Nodes keep what they last read (snapshots readable at any time without waiting) and re-read it on [refresh]. A node
 * is the same object across refreshes for as long as its binding exists.
 *
 * The suspend members and flows of nodes are for Kotlin: Java does not see them (`@JvmSynthetic`), since a
 * `Continuation` is no way to call a remote operation from Java. Java calls them through the facades of
 * `org.rtcoord.java` (`JavaTree`, `JavaComponent`, `JavaPort`, ...), blocking or as a `CompletableFuture`.
 *
 * Only the tree makes nodes: each class is sealed, and the tree makes its one `internal` subclass (`ComponentNodeImpl`,
 * ...). Kotlin compiles a sealed class's constructor as private, which javac cannot call; an `internal` constructor
 * would be public to javac.
 */
public sealed class Node(
    /** Where the node is: `/host:port/ctx/name.rtc`. */
    public val path: RtcPath,
    @get:JvmSynthetic internal val core: TreeCore,
) {
    /** The last segment of [path]. */
    public val name: String
        get() = path.name

    /** What this node stands for. */
    public abstract val kind: NodeKind

    /**
     * Reads the node again from the live system, and its descendants down to [depth] levels below it (0: this node
     * only; [Int.MAX_VALUE]: the whole subtree), concurrently. Descendants that turn out dead or hung become
     * [ZombieNode]s; a failure of this node itself is thrown.
     */
    @JvmSynthetic public abstract suspend fun refresh(depth: Int = 0)

    override fun toString(): String = "${kind.name.lowercase()} $path"
}
