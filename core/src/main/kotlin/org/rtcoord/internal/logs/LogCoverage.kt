package org.rtcoord.internal.logs

import java.util.Collections
import java.util.IdentityHashMap
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.LogRecord
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.RootNode
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.componentsListed

/**
 * Which records a registration on [target] hears: a component's own; a manager's, and those of the components it hosts;
 * a naming context's or name server's, from the components and managers listed below it; the root's, every record,
 * including those from senders the tree has not listed.
 */
internal fun logCoverage(target: Node, now: () -> Long): (LogRecord) -> Boolean =
    when (target) {
        is RootNode -> { _ ->
            true
        }
        is ComponentNode -> { record ->
            (record.source as? ComponentNode)?.isSameComponent(target) == true
        }
        is DirectoryNode -> Below(target, now)::covers
        else -> { _ ->
            false
        }
    }

/**
 * Whether a record's sender is listed below [directory]: by its path when it is there (a naming context's own
 * components), else among the components the listings below show (a manager's, reached at their naming context), walked
 * at most once every [BELOW_MILLIS] for records from elsewhere, which would otherwise walk them each.
 */
private class Below(private val directory: DirectoryNode, private val now: () -> Long) {
    @Volatile private var listed: Set<ComponentObject> = emptySet()
    @Volatile private var listedAt = Long.MIN_VALUE

    fun covers(record: LogRecord): Boolean =
        when (val source = record.source) {
            is ComponentNode -> source.path.startsWith(directory.path) || source.component in components()
            is ManagerNode -> source.path.startsWith(directory.path)
            else -> false
        }

    private fun components(): Set<ComponentObject> {
        val time = now()
        if (listedAt == Long.MIN_VALUE || time - listedAt >= BELOW_MILLIS) {
            listed =
                componentsListed(listOf(directory)).mapTo(Collections.newSetFromMap(IdentityHashMap())) { it.component }
            listedAt = time
        }
        return listed
    }

    private companion object {
        /** How long what a directory's listings hold is taken as known, as [LogSenders] keeps its answers. */
        const val BELOW_MILLIS = 1_000L
    }
}
