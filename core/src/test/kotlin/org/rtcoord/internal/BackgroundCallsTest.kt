package org.rtcoord.internal

import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.EmptyCoroutineContext
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await

/**
 * The tree's periodic listings fan out on few threads (a coroutine per binding woke a thread each); other work keeps
 * the tree's concurrency.
 */
class BackgroundCallsTest {
    @Test
    fun `a fan-out of calls under background calls runs on their few threads`() {
        val fanOut = fanOut { remote -> BackgroundCalls(remote.dispatcher.limitedParallelism(2)) }
        assertEquals(2, fanOut.mostInFlight)
        assertTrue(fanOut.threads <= 2, "${fanOut.threads} threads ran the fan-out")
    }

    @Test
    fun `a fan-out of calls otherwise has the tree's concurrency in flight`() {
        assertEquals(CONCURRENCY, fanOut { EmptyCoroutineContext }.mostInFlight)
    }

    private class FanOut(val mostInFlight: Int, val threads: Int)

    /**
     * Reads twice [CONCURRENCY] objects at once, as a listing resolves its bindings, in the context [context] makes;
     * each call is held until no more can start.
     */
    private fun fanOut(context: (Remote) -> CoroutineContext): FanOut = runBlocking {
        TreeThreads(CONCURRENCY).use { threads ->
            val remote = Remote(CONCURRENCY, 2.seconds, orbEnforcesDeadline = true, threads)
            val limit = context(remote)[BackgroundCalls]?.let { 2 } ?: CONCURRENCY
            val running = AtomicInteger()
            val most = AtomicInteger()
            val used = ConcurrentHashMap.newKeySet<Thread>()
            val release = CountDownLatch(1)
            val reading =
                async(threads.dispatcher + context(remote)) {
                    withContext(remote.callDispatcher()) {
                        coroutineScope {
                            List(CONCURRENCY * 2) {
                                    async {
                                        used += Thread.currentThread()
                                        remote.call("binding$it", "resolve") {
                                            most.accumulateAndGet(running.incrementAndGet(), ::maxOf)
                                            release.await(10, TimeUnit.SECONDS)
                                            running.decrementAndGet()
                                        }
                                    }
                                }
                                .awaitAll()
                        }
                    }
                }
            // Each call holds its thread until released: one more would start only past the limit.
            await("$limit calls in flight") { running.get() == limit }
            release.countDown()
            reading.await()
            FanOut(most.get(), used.size)
        }
    }

    private companion object {
        const val CONCURRENCY = 6
    }
}
