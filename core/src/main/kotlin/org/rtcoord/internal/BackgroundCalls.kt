package org.rtcoord.internal

import kotlin.coroutines.CoroutineContext
import kotlinx.coroutines.CoroutineDispatcher

/**
 * Marks the tree's periodic listings ([TreeCore.background]): the work under it, and its calls, run on [dispatcher], a
 * few of the tree's threads ([PARALLELISM] at once), instead of the tree's full concurrency. A listing resolves every
 * binding of a context and reads every slave of a manager at once, and the listings of a system all come in the same
 * second: each started a coroutine per binding on a thread of its own, so a coordinator listing seven components every
 * second kept nine threads alive for as long as it ran. Discovery, and whatever a caller waits for, keep the tree's
 * concurrency.
 */
internal class BackgroundCalls(val dispatcher: CoroutineDispatcher) : CoroutineContext.Element {
    override val key: CoroutineContext.Key<*>
        get() = Key

    companion object Key : CoroutineContext.Key<BackgroundCalls> {
        /** How many threads the periodic listings use at once, together. */
        const val PARALLELISM = 2
    }
}
