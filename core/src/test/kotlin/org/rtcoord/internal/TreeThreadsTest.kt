package org.rtcoord.internal

import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.joinAll
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await

/**
 * A tree keeps as few threads as its work needs: a fixed pool kept 32 threads alive under 1 s heartbeats. Still, its
 * coroutines never run more than its concurrency at once, and a timer's task runs on a worker, not on the timer.
 */
class TreeThreadsTest {
    @Test
    fun `coroutines that block run at most concurrency at once`() = runBlocking {
        TreeThreads(concurrency = 4).use { threads ->
            val running = AtomicInteger()
            val most = AtomicInteger()
            val release = CountDownLatch(1)
            val tasks =
                CoroutineScope(threads.dispatcher).run {
                    List(40) {
                        launch {
                            most.accumulateAndGet(running.incrementAndGet(), ::maxOf)
                            release.await(10, TimeUnit.SECONDS)
                            running.decrementAndGet()
                        }
                    }
                }
            // Each holds its thread until released: a fifth would start only past the limit.
            await("four coroutines to block") { running.get() == 4 }
            release.countDown()
            tasks.joinAll()
            assertEquals(4, most.get())
        }
    }

    @Test
    fun `work that comes one task at a time reuses a few workers, and idle ones end`() = runBlocking {
        TreeThreads(concurrency = 32, idle = 300.milliseconds).use { threads ->
            // A burst makes several workers.
            val burst = CountDownLatch(8)
            val workers = ConcurrentHashMap.newKeySet<Thread>()
            repeat(8) {
                threads.submit {
                    workers += Thread.currentThread()
                    burst.countDown()
                    burst.await(5, TimeUnit.SECONDS)
                }
            }
            assertTrue(burst.await(5, TimeUnit.SECONDS))
            // Then one task after another, as heartbeats come: the most recently idle worker takes each. Until the
            // burst's workers are all back waiting for work (on a busy machine, a while), any of them may take one.
            await("20 tasks one at a time to run on at most 3 workers") {
                runBlocking { List(20) { withContext(threads.dispatcher) { Thread.currentThread().name } } }
                    .toSet()
                    .size <= 3
            }
            await("the burst's idle workers end") { workers.count(Thread::isAlive) <= 3 }
        }
    }

    @Test
    fun `a timed task runs on a worker once its time has passed`() {
        TreeThreads(concurrency = 2).use { threads ->
            val ran = CountDownLatch(1)
            var thread = ""
            val start = System.nanoTime()
            var after = 0L
            threads.schedule(50_000_000) {
                after = System.nanoTime() - start
                thread = Thread.currentThread().name
                ran.countDown()
            }
            assertTrue(ran.await(5, TimeUnit.SECONDS))
            assertTrue(after >= 50_000_000, "ran after ${after / 1000} us")
            assertTrue(thread.startsWith("rtcoord-tree-"), "ran on $thread")
        }
    }
}
