package org.rtcoord.dsl

import java.nio.file.Paths
import java.time.Instant
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.test.advanceTimeBy
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.internal.Configurator
import org.rtcoord.dsl.internal.Engine
import org.rtcoord.dsl.internal.Identities
import org.rtcoord.dsl.internal.MachineInterpreter

/** The state machine core on virtual time: timeouts, nesting, entry and exit order, without a live system. */
class MachineInterpreterTest {
    @Test
    fun `timeouts move the machine, outer ones keep running in sub-modes, and a left mode's timers stop`() = runTest {
        val trace = mutableListOf<String>()
        val failures = mutableListOf<String>()
        val machine =
            Coordination(emptyList(), TreeConfig()).modes("m") {
                initial("a")
                mode("a") {
                    entry { trace += "enter a at ${testScheduler.currentTime}" }
                    exit { trace += "exit a" }
                    after(5.seconds) goTo "b"
                }
                mode("b") {
                    entry { trace += "enter b" }
                    exit { trace += "exit b" }
                    initial("b1")
                    after(10.seconds).goTo("a") { trace += "action b -> a" }
                    mode("b1") {
                        exit { trace += "exit b1" }
                        after(2.seconds) goTo "b2"
                        // Cancelled when b1 is left at 7 s; had it fired at 25 s it would count as unconsumed.
                        after(20.seconds) goTo "a"
                    }
                    mode("b2") {
                        entry { trace += "enter b2 at ${testScheduler.currentTime}" }
                        exit { trace += "exit b2" }
                    }
                }
            }
        val engine = engine(backgroundScope)
        val interpreter =
            MachineInterpreter(
                machine,
                backgroundScope,
                engine,
                Configurator(engine, backgroundScope),
                log = {},
                failed = { what, e -> failures += "$what: $e" },
                now = { Instant.ofEpochMilli(testScheduler.currentTime) },
            )
        interpreter.start()
        runCurrent()
        assertEquals("m/a", interpreter.running.mode.value)

        advanceTimeBy(31.seconds)
        runCurrent()
        fun move(from: String?, to: String, trigger: String, seconds: Long) =
            ModeTransition(from, to, trigger, Instant.ofEpochSecond(seconds))
        assertEquals(
            listOf(
                move(null, "m/a", "start", 0),
                move("m/a", "m/b/b1", "after 5s", 5),
                move("m/b/b1", "m/b/b2", "after 2s", 7),
                move("m/b/b2", "m/a", "after 10s", 15),
                move("m/a", "m/b/b1", "after 5s", 20),
                move("m/b/b1", "m/b/b2", "after 2s", 22),
                move("m/b/b2", "m/a", "after 10s", 30),
            ),
            interpreter.running.history.value,
        )
        assertEquals(
            listOf(
                "enter a at 0",
                "exit a",
                "enter b",
                "exit b1",
                "enter b2 at 7000",
                "exit b2",
                "exit b",
                "action b -> a",
                "enter a at 15000",
            ),
            trace.take(9),
        )
        assertEquals(0, interpreter.running.unconsumed, "no stale timeout reached the machine")
        assertEquals(emptyList<String>(), failures)
    }

    @Test
    fun `a failing entry action is reported and the machine still enters the mode`() = runTest {
        val failures = mutableListOf<String>()
        val machine =
            Coordination(emptyList(), TreeConfig()).modes("m") {
                initial("a")
                mode("a") { after(1.seconds) goTo "b" }
                mode("b") { entry { error("cannot start b") } }
            }
        val engine = engine(backgroundScope)
        val interpreter =
            MachineInterpreter(
                machine,
                backgroundScope,
                engine,
                Configurator(engine, backgroundScope),
                log = {},
                failed = { what, e -> failures += "$what: ${e.message}" },
            )
        interpreter.start()
        advanceTimeBy(2.seconds)
        runCurrent()
        assertEquals("m/b", interpreter.running.mode.value)
        assertEquals(listOf("entry of m/b: cannot start b"), failures)
    }

    private val tree = RtcTree()

    @AfterEach fun closeTree() = tree.close()

    /** An engine on a tree that knows no name server: these machines never act on the system. */
    private fun engine(scope: CoroutineScope) =
        Engine(tree, Identities(tree, EventOptions(), scope, {}, emptyMap()), Paths.get(""), {})
}
