package org.rtcoord.bench

import java.lang.management.ManagementFactory
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeout
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.Coordinator
import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.DataType
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.rtSystem

/**
 * Data taps: a scanner fixture in this JVM writes TimedDoubleSeq(181) at 100 Hz and 1 kHz; the tree taps its out-port.
 * Latency is from just before the fixture's write (its encode and push included) to the tap's listener, matched by the
 * scan's first value (its tick). CPU per sample is what tapping adds to this JVM (push, receipt, decode, delivery) over
 * the same fixture running untapped. Silence detection delay is from freezing the scanner's output to a coordinator's
 * `silentFor` handler, less the threshold.
 */
internal class DataBench(private val options: BenchOptions, private val report: Report) {
    private val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean
    private val written = ConcurrentHashMap<Long, Long>()
    private val writes = AtomicLong()

    private fun scanner(rate: Double) =
        ComponentType(
            "scanner",
            listOf(PortSpec.DataOut("scan", DataType.TIMED_DOUBLE_SEQ)),
            rate = rate,
            behaviour = {
                Behaviour.source("scan") { tick ->
                    written[tick] = System.nanoTime()
                    writes.incrementAndGet()
                    DoubleArray(SCAN) { if (it == 0) tick.toDouble() else 4.0 }
                }
            },
        )

    suspend fun run() {
        report.section(
            "data: tap of a TimedDoubleSeq($SCAN) out-port, fixture in the bench JVM; ${options.dataWindow} windows"
        )
        for (rate in listOf(100.0, 1000.0)) rate(rate)
        silence()
    }

    private suspend fun rate(rate: Double) {
        written.clear()
        NamingService.start().use { naming ->
            rtSystem(naming.corbaloc) {
                    component(scanner(rate), "scanner0")
                    activate("scanner0")
                }
                .use {
                    RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                        val port = tree.port("/${naming.address}/${RuntimeProcess.hostContext}/scanner0.rtc:scan")
                        delay(options.dataWindow / 2) // warm-up, untapped
                        val idleCpu = cpuPerSecond(options.dataWindow)
                        val latencies = ConcurrentLinkedQueue<Long>()
                        var counting = false
                        val subscription = port.tap { data ->
                            val received = System.nanoTime()
                            val tick = (data as? TimedDoubleSeq)?.data?.firstOrNull()?.toLong() ?: return@tap
                            val sent = written.remove(tick) ?: return@tap
                            if (counting) latencies += received - sent
                        }
                        delay(options.dataWindow / 2) // warm-up, tapped
                        counting = true
                        val writesBefore = writes.get()
                        val tappedCpu = cpuPerSecond(options.dataWindow)
                        val wrote = (writes.get() - writesBefore) / options.dataWindow.inWholeMilliseconds.times(1e-3)
                        counting = false
                        subscription.cancel()
                        val samples = latencies.toList()
                        if (samples.isEmpty()) return report.skipped("${figure(rate)} Hz", "no sample reached the tap")
                        val millis = Samples.millis(samples)
                        val received = samples.size / options.dataWindow.inWholeMilliseconds.times(1e-3)
                        report.row(
                            "write to listener at ${figure(rate)} Hz",
                            millis,
                            "p50 ${figure(millis.percentile(50.0))} ms, p99 ${figure(millis.percentile(99.0))} ms; the fixture wrote ${figure(wrote)}/s, ${figure(received)}/s reached the tap (its connector is of subscription type new: the newest sample, not a queue)",
                        )
                        report.value(
                            "CPU per sample at ${figure(rate)} Hz",
                            (tappedCpu - idleCpu) / received * 1e6,
                            "us",
                            "tapped ${figure(tappedCpu * 100)} % of a core, untapped ${figure(idleCpu * 100)} %",
                        )
                    }
                }
        }
    }

    /** This JVM's CPU time per second over [window], in cores. */
    private suspend fun cpuPerSecond(window: Duration): Double {
        val cpuBefore = os.processCpuTime
        val before = System.nanoTime()
        delay(window)
        return (os.processCpuTime - cpuBefore).toDouble() / (System.nanoTime() - before)
    }

    private suspend fun silence() {
        NamingService.start().use { naming ->
            rtSystem(naming.corbaloc) {
                    component(scanner(100.0), "scanner0")
                    activate("scanner0")
                }
                .use { system ->
                    val config = TreeConfig(listOf(naming.address))
                    RtcTree(config).use { tree ->
                        val fixture = system.component("scanner0")
                        for (threshold in listOf(100.milliseconds, 500.milliseconds, 1.seconds)) {
                            val delays =
                                List(options.silenceRepetitions) {
                                    var fired = CompletableDeferred<Long>()
                                    val coordination =
                                        Coordination(emptyList(), config).apply {
                                            on(port("scanner0.rtc:scan")).silentFor(threshold) {
                                                fired.complete(System.nanoTime())
                                            }
                                        }
                                    Coordinator(tree, coordination, EventOptions(WatchMode.PUSH)).use { coordinator ->
                                        coordinator.start()
                                        delay(threshold * 2) // scans flowing: no silence yet
                                        fired = CompletableDeferred()
                                        val frozen = System.nanoTime()
                                        fixture.freezeOutput()
                                        val noticed = withTimeout(threshold * 3 + 5.seconds) { fired.await() }
                                        fixture.thawOutput()
                                        noticed - frozen - threshold.inWholeNanoseconds
                                    }
                                }
                            val millis = Samples.millis(delays)
                            report.row(
                                "silence noticed after ${threshold.inWholeMilliseconds} ms",
                                millis,
                                "beyond the threshold; checks every threshold / 5 (10 to 200 ms)",
                            )
                        }
                    }
                }
        }
    }

    private companion object {
        const val SCAN = 181
    }
}
