package org.rtcoord.internal

import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.Node
import org.rtcoord.RtcException

/**
 * Every component at or below [tops] once, at its canonical path: the one walk over the listings that says which
 * components the tree knows and where (the tree's snapshot, `componentNamed`, a capture, a script's globs and the CLI's
 * views all take it from here). [children] gives a directory's listing, or null to skip it; of a component's paths
 * where [predicate] holds, the one kept is the canonical one ([ComponentNode.canonical]), or by the same rule among
 * them when that one is not (a naming path before a manager's listing, which is an alias). In the order the walk, depth
 * first, first reached each component. Inline so that [children] and [predicate] may suspend where the caller may.
 */
@InternalRtcoordApi
public inline fun componentsOnce(
    tops: Iterable<Node>,
    children: (DirectoryNode) -> List<Node>?,
    predicate: (ComponentNode) -> Boolean = { true },
): List<ComponentNode> {
    val found = ArrayList<ComponentNode>()
    val pending = ArrayDeque<Node>()
    pending.addAll(tops)
    while (pending.isNotEmpty()) {
        when (val node = pending.removeFirst()) {
            is ComponentNode -> if (predicate(node)) found += node
            is DirectoryNode -> children(node)?.let { pending.addAll(0, it) }
            else -> Unit
        }
    }
    return canonicalOnce(found)
}

/** [componentsOnce] from what the listings hold now, without a remote call. */
@InternalRtcoordApi
public inline fun componentsListed(
    tops: Iterable<Node>,
    predicate: (ComponentNode) -> Boolean = { true },
): List<ComponentNode> = componentsOnce(tops, { it.listed.value }, predicate)

/**
 * [componentsOnce], listing each directory that never was as the walk reaches it; one that cannot be listed is skipped.
 */
@InternalRtcoordApi
public suspend inline fun componentsFound(
    tops: Iterable<Node>,
    predicate: (ComponentNode) -> Boolean = { true },
): List<ComponentNode> =
    componentsOnce(
        tops,
        { directory ->
            try {
                directory.children()
            } catch (e: RtcException) {
                null
            }
        },
        predicate,
    )

/** One node of each component among [found], its canonical one, in the order [found] first names each. */
@PublishedApi
internal fun canonicalOnce(found: List<ComponentNode>): List<ComponentNode> =
    found.groupBy { it.component }.map { (component, nodes) -> component.canonicalAmong(nodes) }
