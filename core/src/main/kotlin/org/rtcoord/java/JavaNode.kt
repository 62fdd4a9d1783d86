package org.rtcoord.java

import org.jspecify.annotations.Nullable
import org.rtcoord.Node
import org.rtcoord.NodeKind
import org.rtcoord.RtcException
import org.rtcoord.ZombieNode

/**
 * A node of the tree for Java callers: where it is, its name and kind, and for a dead registration why (see [Node]).
 * Operate on it through [JavaTree.component], [JavaTree.manager] and [JavaTree.port] with its [path]. Two facades of
 * the same node are equal; `new JavaNode(node)` shows a node at hand.
 */
public class JavaNode(
    /** The node shown. */
    private val node: Node
) {
    /** Where the node is: `/host:port/ctx/name.rtc`. */
    public val path: String
        get() = node.path.toString()

    /** The last segment of [path]: `laser0.rtc`. */
    public val name: String
        get() = node.name

    /** What the node stands for. */
    public val kind: NodeKind
        get() = node.kind

    /** Why the object is taken for dead when the node is a zombie ([NodeKind.ZOMBIE]); null otherwise. */
    public val deathCause: @Nullable RtcException?
        get() = (node as? ZombieNode)?.cause

    override fun equals(other: @Nullable Any?): Boolean = other is JavaNode && other.node === node

    override fun hashCode(): Int = System.identityHashCode(node)

    override fun toString(): String = node.toString()
}
