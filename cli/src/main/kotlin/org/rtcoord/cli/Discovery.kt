package org.rtcoord.cli

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.Node

/**
 * Reads [from] and everything below it again, [depth] levels down, concurrently (dead and hung objects become zombies):
 * whole components, or with [summaries] only what listings show of them. When that takes more than half a second,
 * [progress] (if any) shows how far it got.
 */
internal suspend fun discover(
    from: Node,
    progress: StatusLine?,
    summaries: Boolean = false,
    depth: Int = Int.MAX_VALUE,
): Unit = coroutineScope {
    val ticker = progress?.let { line ->
        launch {
            delay(PROGRESS_AFTER)
            while (true) {
                val (components, directories) = countKnown(from)
                line.show("rtcoord: discovering: $components components in $directories directories so far")
                delay(PROGRESS_EVERY)
            }
        }
    }
    try {
        if (summaries && from is DirectoryNode) from.survey(depth) else from.refresh(depth)
    } finally {
        ticker?.cancel()
        progress?.clear()
    }
}

/** Components read and directories listed below [node] so far, from what the tree holds (no calls). */
private fun countKnown(node: Node): Pair<Int, Int> =
    when (node) {
        is ComponentNode -> (if (node.summaries.value != null) 1 else 0) to 0
        is DirectoryNode ->
            node.listed.value.orEmpty().map(::countKnown).fold(0 to 1) { (components, directories), (c, d) ->
                components + c to directories + d
            }
        else -> 0 to 0
    }

private val PROGRESS_AFTER = 500.milliseconds
private val PROGRESS_EVERY = 250.milliseconds
