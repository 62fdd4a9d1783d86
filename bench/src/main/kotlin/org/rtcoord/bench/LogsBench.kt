package org.rtcoord.bench

import java.lang.management.ManagementFactory
import java.nio.file.Paths
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.LogInput
import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.Coordinator
import org.rtcoord.fixtures.FixtureProcess

/**
 * What components' log records cost the coordinator (the issue's "10,000 records a second from 100 senders, each
 * delivered to a rule, under 10% of a core"): the localisation system in a fixture JVM, the senders in a JVM of their
 * own ([LogSenderMain], Message mode, each record naming one of the system's components as its logger, as OpenRTM-aist
 * names a component's), and in the bench JVM only the tree with its log input and a coordinator whose rules hear each
 * component's records (`on(component(...)).logged(...)`): each record delivered to one rule, as the issue has it; then
 * again with a rule on every record (`on(logs())`) too, two rules a record. The bench JVM's process CPU time, sampled
 * each second once the JIT is quiet, is the receiving side's. Then memory: a handler that never returns (a slow view)
 * while a flood arrives, the live heap after GC and what the input dropped.
 */
internal class LogsBench(private val options: BenchOptions, private val report: Report) {
    private val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean

    suspend fun run() {
        FixtureProcess.start("--scenario", "localisation", timeout = 2.minutes).use { fixtures ->
            rate(fixtures.address, everyRecordToo = false)
            rate(fixtures.address, everyRecordToo = true)
            flood(fixtures.address)
        }
    }

    /**
     * The receiving side's CPU with each record heard by the rule on its component (the issue's "each delivered to a
     * rule") or, with [everyRecordToo], by `on(logs())` as well: two rules a record.
     */
    private suspend fun rate(address: String, everyRecordToo: Boolean) {
        val senders = options.logSenders
        val rate = options.logRate
        val window = options.logWindow
        val heardBy = if (everyRecordToo) "its component's rule and on(logs())" else "its component's rule"
        report.section(
            "logs: $rate records/s from $senders senders (Message mode, a JVM of their own), each heard by $heardBy; ${window.inWholeSeconds} s window after at least ${options.logWarmup.inWholeSeconds} s warm-up, until the JIT is quiet"
        )
        RtcTree(TreeConfig(listOf(address))).use { tree ->
            tree.refresh()
            val input = tree.listenForLogs("127.0.0.1:0")
            val everyRecord = AtomicLong()
            val attributed = ConcurrentHashMap<String, AtomicLong>()
            val coordination =
                Coordination(emptyList(), TreeConfig(listOf(address)), name = "logs bench").apply {
                    if (everyRecordToo) on(logs()).level(LogLevel.PARANOID) { everyRecord.incrementAndGet() }
                    for (name in COMPONENTS) {
                        on(component("$name.rtc")).logged(LogLevel.PARANOID) { record ->
                            attributed.getOrPut(record.source.name) { AtomicLong() }.incrementAndGet()
                        }
                    }
                }
            Coordinator(tree, coordination).use { coordinator ->
                coordinator.start()
                val seconds = (options.logWarmupLimit + window).inWholeSeconds + 1
                SenderProcess.start(input, senders, rate.toDouble(), seconds).use { sending ->
                    sending.awaitLine("started", 1.minutes)
                    val warmUp = warmUp()
                    val cpu = mutableListOf<Double>()
                    val receivedBefore = input.received
                    val compiledBefore = JitCompilation.millis()
                    var cpuBefore = os.processCpuTime
                    var before = System.nanoTime()
                    val started = before
                    repeat(window.inWholeSeconds.toInt().coerceAtLeast(1)) {
                        delay(1.seconds)
                        val cpuNow = os.processCpuTime
                        val now = System.nanoTime()
                        cpu += 100.0 * (cpuNow - cpuBefore) / (now - before)
                        cpuBefore = cpuNow
                        before = now
                    }
                    val receivedRate = (input.received - receivedBefore) * 1e9 / (System.nanoTime() - started)
                    val compiled = compiledBefore?.let { JitCompilation.millis()?.minus(it) }
                    val sent = sending.stop(1.minutes)
                    // Every record sent should reach the rules; wait for the last ones, within a deadline.
                    withTimeoutOrNull(30.seconds) {
                        while (
                            (everyRecordToo && everyRecord.get() < sent) || attributed.values.sumOf { it.get() } < sent
                        ) delay(10)
                    }
                    val heard = attributed.values.sumOf { it.get() }
                    report.row(
                        "receiving CPU",
                        Samples(cpu, "% core"),
                        "mean ${figure(cpu.average())}% of one core at ${figure(receivedRate)} records/s received, per-second samples, after ${warmUp.inWholeSeconds} s warm-up; the JIT compiled ${compiled ?: "?"} ms in the window; target: under 10% of one core",
                    )
                    if (everyRecordToo) {
                        report.value(
                            "records delivered to on(logs())",
                            everyRecord.get().toDouble(),
                            "records",
                            "of $sent sent (${sending.failed} could not be sent)",
                        )
                    }
                    report.value(
                        "records attributed to components",
                        heard.toDouble(),
                        "records",
                        "of $sent sent (${sending.failed} could not be sent), heard by on(component(...)).logged rules: " +
                            attributed.entries.sortedBy { it.key }.joinToString { "${it.key} ${it.value.get()}" } +
                            "; input received ${input.received}, refused ${input.refusals().filterValues { it > 0 }}",
                    )
                    report.value("handler failures", coordinator.failures.toDouble(), "failures")
                }
            }
        }
    }

    /**
     * Waits [BenchOptions.logWarmup], then until [QUIET_SECONDS] seconds in a row in each of which the JIT compiled
     * less than [QUIET_JIT_MILLIS], at most [BenchOptions.logWarmupLimit] in all: C2 compiling the record path (it
     * comes in bursts) is the JVM's start, not what records cost a running coordinator. Returns how long it waited.
     */
    private suspend fun warmUp(): Duration {
        val started = System.nanoTime()
        delay(options.logWarmup)
        var quiet = 0
        while (quiet < QUIET_SECONDS && (System.nanoTime() - started).nanoseconds < options.logWarmupLimit) {
            val before = JitCompilation.millis() ?: break
            delay(1.seconds)
            quiet = if ((JitCompilation.millis() ?: break) - before < QUIET_JIT_MILLIS) quiet + 1 else 0
        }
        return (System.nanoTime() - started).nanoseconds
    }

    private suspend fun flood(address: String) {
        val flood = options.logFlood
        val senders = FLOOD_SENDERS
        report.section(
            "logs: memory while a slow view holds its first record and $flood more arrive ($senders senders, as fast as they send)"
        )
        RtcTree(TreeConfig(listOf(address))).use { tree ->
            tree.refresh()
            val input = tree.listenForLogs("127.0.0.1:0")
            val release = CompletableDeferred<Unit>()
            val seen = AtomicLong()
            // The slow view: its handler takes a record and never comes back for the next until released.
            val view =
                tree.on(tree.root, LogRecord::class.java) {
                    seen.incrementAndGet()
                    release.await()
                }
            val before = Heap.live()
            val started = System.nanoTime()
            SenderProcess.start(input, senders, 0.0, flood / senders.toLong()).use { sending ->
                sending.awaitLine("started", 1.minutes)
                val sent = sending.sent(10.minutes)
                withTimeoutOrNull(60.seconds) { while (input.received < sent) delay(10) }
                val seconds = (System.nanoTime() - started) / 1e9
                val live = Heap.live()
                val dropped = input.refusals()["dropped"] ?: 0
                val slow = input.refusals()["slow-handler"] ?: 0
                report.value(
                    "live heap after GC, view held",
                    live / Heap.MB,
                    "MB",
                    "${figure((live - before) / Heap.MB)} MB over the tree before the flood; $sent sent in ${figure(seconds)} s, ${input.received} received",
                )
                report.value(
                    "records dropped",
                    (dropped + slow).toDouble(),
                    "records",
                    "LogInput.refusals(): $dropped waiting for their sender (\"dropped\"), $slow waiting for the view (\"slow-handler\"); the view took ${seen.get()}",
                )
            }
            release.complete(Unit)
            view.cancel()
        }
    }

    /** A [LogSenderMain] process, its output read line by line. */
    private class SenderProcess(private val process: Process) : AutoCloseable {
        private val lines = linesOf(process, "log-senders-output")
        var failed = 0L
            private set

        fun awaitLine(prefix: String, timeout: Duration): String {
            val deadline = System.nanoTime() + timeout.inWholeNanoseconds
            while (true) {
                val line =
                    lines.poll((deadline - System.nanoTime()).coerceAtLeast(0), TimeUnit.NANOSECONDS)
                        ?: error("the log senders printed no '$prefix' within $timeout")
                if (line.startsWith(prefix)) return line
            }
        }

        /** Waits for the senders to end; how many records they sent. */
        fun sent(timeout: Duration): Long {
            val words = awaitLine("sent ", timeout).split(' ')
            failed = words[3].toLong()
            return words[1].toLong()
        }

        /** Tells the senders to stop now; how many records they sent. */
        fun stop(timeout: Duration): Long {
            process.outputStream.close()
            return sent(timeout)
        }

        override fun close() {
            if (process.isAlive) process.destroyForcibly().waitFor(10, TimeUnit.SECONDS)
        }

        companion object {
            fun start(input: LogInput, senders: Int, rate: Double, amount: Long): SenderProcess {
                val java = Paths.get(System.getProperty("java.home"), "bin", "java").toString()
                val command =
                    listOf(
                        java,
                        "-cp",
                        System.getProperty("java.class.path"),
                        "org.rtcoord.bench.LogSenderMain",
                        input.port.toString(),
                        MANAGER,
                        COMPONENTS.joinToString(","),
                        senders.toString(),
                        rate.toString(),
                        amount.toString(),
                    )
                return SenderProcess(ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start())
            }
        }
    }

    private companion object {
        /** The localisation system's components, hosted by [MANAGER]: the senders' loggers. */
        val COMPONENTS = listOf("laser0", "gyro0", "odometry0", "laser_localise0")
        const val MANAGER = "manager_slave"
        const val FLOOD_SENDERS = 10

        /** Less compiled in a second than this, and the JIT is quiet enough to measure. */
        const val QUIET_JIT_MILLIS = 20L
        const val QUIET_SECONDS = 3
    }
}
