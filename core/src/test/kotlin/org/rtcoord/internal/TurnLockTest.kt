package org.rtcoord.internal

import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.yield
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

class TurnLockTest {
    @Test
    fun `turns come one at a time in the order they were asked for`() = runTest {
        val lock = TurnLock()
        val log = CopyOnWriteArrayList<String>()
        val release = CompletableDeferred<Unit>()
        val first = launch {
            lock.withTurn {
                log += "first in"
                release.await()
                log += "first out"
            }
        }
        yield()
        val second = launch { lock.withTurn { log += "second" } }
        val third = launch { lock.withTurn { log += "third" } }
        yield()
        assertEquals(listOf("first in"), log.toList(), "nobody runs while a turn is on")
        release.complete(Unit)
        listOf(first, second, third).forEach { it.join() }
        assertEquals(listOf("first in", "first out", "second", "third"), log.toList())
    }

    @Test
    fun `a turn given up while waiting holds the ones after it only until the one before it is over`() = runTest {
        val lock = TurnLock()
        val log = CopyOnWriteArrayList<String>()
        val release = CompletableDeferred<Unit>()
        val first = launch {
            lock.withTurn {
                release.await()
                log += "first"
            }
        }
        yield()
        val givenUp = launch(start = CoroutineStart.UNDISPATCHED) { lock.withTurn { log += "given up" } }
        val third = launch(start = CoroutineStart.UNDISPATCHED) { lock.withTurn { log += "third" } }
        givenUp.cancel()
        yield()
        assertEquals(emptyList<String>(), log.toList(), "the third waits for the first")
        release.complete(Unit)
        listOf(first, third).forEach { it.join() }
        assertEquals(listOf("first", "third"), log.toList())
        assertEquals("free", lock.withTurn { "free" }, "the lock is free once every turn is over")
    }

    @Test
    fun `a turn whose block throws is over`() = runTest {
        val lock = TurnLock()
        runCatching { lock.withTurn { error("read failed") } }
        assertEquals(1, lock.withTurn { 1 })
    }
}
