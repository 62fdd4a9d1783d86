package org.rtcoord

import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.internal.TreeCore

/**
 * A node with children: the root, a name server, a naming context or a manager. Children are listed
 * on first use and again on [refresh]; nodes whose binding is still there are kept, new bindings appear
 * and vanished ones disappear.
 */
public sealed class DirectoryNode(path: RtcPath, core: TreeCore) : Node(path, core) {
    private val listing = MutableStateFlow<List<Node>?>(null)
    private val listingLock = Mutex()

    /** The children as last listed, or null before the first listing. Never waits. */
    public val listed: StateFlow<List<Node>?> get() = listing

    /** The children, listed now if they never were. */
    public suspend fun children(): List<Node> = listing.value ?: relist()

    /** The child named [name], listing the children again once if it is not among them. */
    public suspend fun child(name: String): Node? =
        children().firstOrNull { it.name == name } ?: relist().firstOrNull { it.name == name }

    override suspend fun refresh(depth: Int) {
        val children = relist()
        if (depth > 0) coroutineScope { children.forEach { child -> launch { child.refreshOrBury(depth - 1) } } }
    }

    /** Lists the children from the live system, reusing [previous] nodes that still stand. */
    internal abstract suspend fun readChildren(previous: List<Node>): List<Node>

    /** Shows [children] without reading them: the tree already knows them. */
    internal fun show(children: List<Node>) {
        listing.value = children
    }

    internal suspend fun relist(): List<Node> = listingLock.withLock {
        readChildren(listing.value.orEmpty()).also { listing.value = it }
    }

    /** Refreshes [this] child; if it turns out dead, its parent shows a zombie in its place. */
    private suspend fun Node.refreshOrBury(depth: Int) {
        try {
            refresh(depth)
        } catch (e: UnreachableException) {
            bury(this, e)
        } catch (e: TimedOutException) {
            bury(this, e)
        }
    }

    private suspend fun bury(child: Node, cause: RtcException) {
        listingLock.withLock {
            listing.value = listing.value?.map { if (it === child) ZombieNode(child.path, core, cause, this) else it }
        }
    }
}
