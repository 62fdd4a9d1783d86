package org.rtcoord

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.flow.updateAndGet
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import kotlinx.coroutines.withContext
import org.rtcoord.internal.SurveyReads
import org.rtcoord.internal.TreeCore

/**
 * A node with children: the root, a name server, a naming context or a manager. Children are listed on first use and
 * again on [refresh]; nodes whose binding is still there are kept, new bindings appear and vanished ones disappear.
 */
public sealed class DirectoryNode(path: RtcPath, core: TreeCore) : Node(path, core) {
    private val listing = MutableStateFlow<List<Node>?>(null)
    private val listingLock = Mutex()

    /** The children as last listed, or null before the first listing. Never waits. */
    @get:JvmSynthetic
    public val listed: StateFlow<List<Node>?>
        get() = listing

    /** The children, listed now if they never were. */
    @JvmSynthetic public suspend fun children(): List<Node> = listing.value ?: relist()

    /** The child named [name], listing the children again once if it is not among them. */
    @JvmSynthetic
    public suspend fun child(name: String): Node? =
        children().firstOrNull { it.name == name } ?: relist().firstOrNull { it.name == name }

    @JvmSynthetic
    override suspend fun refresh(depth: Int): Unit =
        withContext(core.remote.dispatcher) {
            val children = relist()
            if (depth > 0) children.forEach { child -> launch { buryIfDead(child) { child.refresh(depth - 1) } } }
        }

    /**
     * Lists this directory again, and those below it down to [depth] levels, reading of each component only its
     * [ComponentSummary]: what a listing shows, in fewer calls than [refresh]. A component reached by two paths (its
     * naming context and its manager) is read once. Dead and hung components become [ZombieNode]s, as with [refresh].
     */
    @JvmSynthetic
    public suspend fun survey(depth: Int = Int.MAX_VALUE): Unit =
        withContext(core.remote.dispatcher + (SurveyReads.current() ?: SurveyReads())) {
            val children = relist()
            if (depth > 0) {
                children.forEach { child ->
                    launch {
                        buryIfDead(child) {
                            when (child) {
                                is DirectoryNode -> child.survey(depth - 1)
                                is ComponentNode -> child.refreshSummary()
                                else -> child.refresh(depth - 1)
                            }
                        }
                    }
                }
            }
        }

    /**
     * Lists the children from the live system, reusing [previous] nodes that still stand; a previous node that [kept]
     * accepts is reused as it is while its binding stands, without resolving the binding again.
     */
    @JvmSynthetic internal abstract suspend fun readChildren(previous: List<Node>, kept: (Node) -> Boolean): List<Node>

    /**
     * What to show of [listed], children just listed or shown as they are: the children themselves, unless the
     * directory's children also change without a listing (the root's name servers).
     */
    @JvmSynthetic internal open fun settled(listed: List<Node>): List<Node> = listed

    /**
     * Whether a child whose read failed with [failure] is shown as a [ZombieNode] instead of failing this directory's
     * read.
     */
    @JvmSynthetic internal open fun buries(failure: RtcException): Boolean = failure.meansDead

    /** Shows the children as [settled] says they are now, without reading them. */
    @JvmSynthetic
    internal fun showSettled() {
        listing.update { settled(it.orEmpty()) }
    }

    /** Lists the children again; those [kept] accepts are not read again while their bindings stand. */
    @JvmSynthetic
    internal suspend fun relist(kept: (Node) -> Boolean = { false }): List<Node> = listingLock.withLock {
        val listed = withContext(core.remote.callDispatcher()) { readChildren(listing.value.orEmpty(), kept) }
        // Every write of the listing is an update that starts again if another write came first, so that a
        // child shown meanwhile (a name server added during a refresh) is never written over.
        listing.updateAndGet { settled(listed) }!!
    }

    /** Reads [child] with [read]; if it fails in a way this directory [buries], it shows a zombie in its place. */
    private suspend fun buryIfDead(child: Node, read: suspend () -> Unit) {
        try {
            read()
        } catch (e: RtcException) {
            if (!buries(e)) throw e
            bury(child, e)
        }
    }

    private suspend fun bury(child: Node, cause: RtcException) {
        listingLock.withLock {
            listing.update { children ->
                children?.map { if (it === child) ZombieNodeImpl(child.path, core, cause, this) else it }
            }
        }
    }
}
