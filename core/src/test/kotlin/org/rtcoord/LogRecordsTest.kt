package org.rtcoord

import java.net.InetSocketAddress
import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.FluentLogSender
import org.rtcoord.runtime.RuntimeProcess

/**
 * Log records sent as OpenRTM-aist sends them to a Fluentd input (the runtime's sender, over real TCP in the forward
 * protocol) become events: from the component that logged them, numbered among the tree's events, heard by whoever
 * watches it or what holds it, and costing no watching of their own.
 */
class LogRecordsTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree
    private val input = tree.listenForLogs("127.0.0.1:0")
    private val senders = mutableListOf<FluentLogSender>()

    @AfterEach
    fun stop() {
        senders.forEach(FluentLogSender::close)
        localisation.close()
    }

    /** A sender of records from a process whose manager is [manager], as its `rtc.conf` would make one. */
    private fun sender(manager: String) =
        FluentLogSender(
                InetSocketAddress(input.host, input.port),
                manager,
            )
            .also { senders += it }

    @Test
    fun `a component's record comes from it, numbered among the tree's events, and watches nothing`(): Unit =
        runBlocking {
            localisation.system.runtime.sendLogsTo(InetSocketAddress("127.0.0.1", port()), SLAVE)
            val laser = tree.component(localisation.path("laser0.rtc"))
            val recorder = EventRecorder()
            tree.on(laser, LogRecord::class.java, handler = recorder.handler)
            val before = tree.snapshot().sequence

            assertTrue(
                localisation.system.runtime.components
                    .single { it.instanceName == "laser0" }
                    .log("WARN", "scan timeout")
            )

            val record = recorder.next<LogRecord>()
            assertEquals(laser.path, record.source.path)
            assertEquals(LogLevel.WARN, record.level)
            assertEquals("scan timeout", record.message)
            assertEquals("laser0", record.logger)
            assertEquals(SLAVE, record.manager)
            assertEquals(ProcessHandle.current().pid(), record.pid)
            assertEquals("rtclog", record.tag)
            assertTrue(record.sequence > before, "numbered after the snapshot taken before it: ${record.sequence}")
            assertTrue(tree.snapshot().sequence >= record.sequence)
            assertEquals(1, input.received)
            // Hearing records takes no observer: they come from the log input, not from the component.
            assertTrue(localisation.system.component("laser0").observerIds.isEmpty())
        }

    @Test
    fun `a context hears the records of the components below it, the root those of senders nobody listed`(): Unit =
        runBlocking {
            val everything = EventRecorder()
            val context = EventRecorder()
            tree.on(tree.root, LogRecord::class.java, handler = everything.handler)
            tree.on(tree.node(localisation.host), LogRecord::class.java, handler = context.handler)

            sender("elsewhere").send("ghost", "ERROR", "who am I")
            val ghost = everything.next<LogRecord>()
            assertEquals(RtcPath("/"), ghost.source.path, "a sender no listing shows is the root's: $ghost")
            assertEquals(LogLevel.ERROR, ghost.level)

            // Sent after the ghost's was published: had the context heard the ghost's, it would come first.
            sender(SLAVE).send("gyro0", "INFO", "calibrated")
            val gyro = context.next<LogRecord>()
            assertEquals(localisation.path("gyro0.rtc"), gyro.source.path.toString())
            assertEquals("calibrated", gyro.message)
            assertEquals(gyro, everything.next<LogRecord>())
        }

    @Test
    fun `a record named as OpenRTM-aist-Python names every component's comes from its manager`(): Unit = runBlocking {
        val everything = EventRecorder()
        tree.on(tree.root, LogRecord::class.java, handler = everything.handler)

        // FluentLogger.py prefixes logger names with `fluent.`; every Python component's logger is `rtobject`, and
        // Python's logging calls a warning WARNING.
        sender(SLAVE).send("fluent.rtobject", "WARNING", "on_execute took 120 ms")

        val record = everything.next<LogRecord>()
        assertEquals(NodeKind.MANAGER, record.source.kind, "from the manager of its process: $record")
        assertEquals(SLAVE, record.source.name)
        assertEquals(LogLevel.WARN, record.level)
    }

    @Test
    fun `a standalone Python process's record comes from the one component whose profile names its manager`(): Unit =
        runBlocking {
            // A Python manager that is no master binds itself nowhere: the tree sees its component, not it.
            RuntimeProcess.start(localisation.naming.corbaloc, managerName = STANDALONE).use { process ->
                process.create(ComponentType("warner"))
                val everything = EventRecorder()
                tree.on(tree.root, LogRecord::class.java, handler = everything.handler)

                sender(STANDALONE).send("fluent.rtobject", "WARNING", "scan timeout")

                val record = everything.next<LogRecord>()
                assertEquals(localisation.path("warner0.rtc"), record.source.path.toString(), "$record")
                assertEquals(STANDALONE, record.manager)
            }
        }

    @Test
    fun `a record whose manager's name a listed manager and an unlisted one share is the root's`(): Unit = runBlocking {
        // Both are `manager_slave`: the listed slave of the localisation system, and a process on its own.
        RuntimeProcess.start(localisation.naming.corbaloc, managerName = SLAVE).use { process ->
            process.create(ComponentType("warner"))
            // Listed and read, as a walk that found no sender leaves them: the managers' listings, the warner's
            // profile.
            tree.refresh()
            tree.component(localisation.path("warner0.rtc")).snapshot()
            val everything = EventRecorder()
            tree.on(tree.root, LogRecord::class.java, handler = everything.handler)

            sender(SLAVE).send("fluent.rtobject", "WARNING", "scan timeout")

            val record = everything.next<LogRecord>()
            assertEquals(RtcPath("/"), record.source.path, "either manager's: $record")
        }
    }

    @Test
    fun `a handler too slow for the records loses the oldest, counted, and holds no more than its queue`(): Unit =
        runBlocking {
            val release = CompletableDeferred<Unit>()
            val taken = AtomicInteger()
            tree.on(tree.root, LogRecord::class.java) {
                taken.incrementAndGet()
                release.await()
            }
            val sent = QUEUE + 2000
            val laser = sender(SLAVE)
            repeat(sent) { assertTrue(laser.send("laser0", "INFO", "scan $it")) }

            // The handler holds the first; of the rest, the queue keeps the newest and every other is counted.
            fun lost() = input.refusals().filterKeys { it == "dropped" || it == "slow-handler" }.values.sum()
            await("every record published or dropped") {
                input.received == sent.toLong() && lost() == sent - 1L - QUEUE
            }
            assertTrue((input.refusals()["slow-handler"] ?: 0) > 0, "the handler's drops: ${input.refusals()}")
            assertEquals(1, taken.get())
            release.complete(Unit)
            await("the queue handed over") { taken.get() == QUEUE + 1 }
        }

    @Test
    fun `an address that is no address is refused, naming it`() {
        val e = assertThrows<IllegalArgumentException> { tree.listenForLogs("localhost") }
        assertEquals("log input address 'localhost': expected HOST:PORT", e.message)
        val taken = assertThrows<java.io.IOException> { tree.listenForLogs(input.address) }
        assertTrue(input.address in taken.message.orEmpty(), taken.message)
    }

    private fun port() = input.port

    private companion object {
        /** The slave manager of the components' process (the master runs in a process of its own). */
        const val SLAVE = "manager_slave"

        /** The manager of a standalone component's process, in no naming context and no master's listing. */
        const val STANDALONE = "warner_manager"
        /** How many records wait for a slow handler of records. */
        const val QUEUE = 10_000
    }
}
