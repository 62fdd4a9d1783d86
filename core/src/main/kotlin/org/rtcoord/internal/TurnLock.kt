package org.rtcoord.internal

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred

/**
 * A lock for coroutines that gives turns in the order they were asked for and holds nothing while free: each component
 * keeps one to serialise its reads, and a tree watching ten thousand components would otherwise keep as many kotlinx
 * `Mutex`es, which weigh some 250 bytes each when nobody waits.
 */
internal class TurnLock {
    /** The latest turn asked for, completed once it is over; null when none is pending. Guarded by this. */
    private var last: CompletableDeferred<Unit>? = null

    /** Runs [block] once every turn asked for before this one is over, and no other turn meanwhile. */
    suspend fun <T> withTurn(block: suspend () -> T): T {
        val mine = CompletableDeferred<Unit>()
        val previous = synchronized(this) { last.also { last = mine } }
        if (previous != null) {
            try {
                previous.await()
            } catch (e: CancellationException) {
                // Given up while waiting: the turns after this one still wait for the one before it.
                previous.invokeOnCompletion { over(mine) }
                throw e
            }
        }
        try {
            return block()
        } finally {
            over(mine)
        }
    }

    private fun over(turn: CompletableDeferred<Unit>) {
        synchronized(this) { if (last === turn) last = null }
        turn.complete(Unit)
    }
}
