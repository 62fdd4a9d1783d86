package org.rtcoord.bench

import java.lang.management.ManagementFactory
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.toList
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.FixtureProcess

/**
 * What watching costs the coordinator: N components served by a fixture JVM of their own, each watched for
 * [StateChanged] (as a rule `on(component).state(...)` does) by push or by polling at 10 Hz. The bench JVM is the
 * coordinator, and nothing else runs in it meanwhile: its process CPU time, sampled each second, is the coordinator's;
 * the fixture JVM's, sampled alongside, is what answering costs the components (on this machine, the same cores).
 * Missed ticks come from [RtcTree.missedPollTicks].
 */
internal class MonitoringBench(private val options: BenchOptions, private val report: Report) {
    private val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean

    /** [process]'s CPU time so far (the kernel counts it in clock ticks, 10 ms). */
    private fun cpuNanos(process: ProcessHandle): Long = process.info().totalCpuDuration().orElseThrow().toNanos()

    suspend fun run() {
        val n = options.monitoredComponents
        val window = options.monitoringWindow
        FixtureProcess.start("--scenario", "scale:$n", timeout = 10.minutes).use { fixtures ->
            report.section(
                "monitoring cost: $n components for $window, after ${options.monitoringWarmup} warm-up (fixtures in a separate JVM; CPU is the bench JVM's, fixtures' CPU theirs)"
            )
            val components = ProcessHandle.of(fixtures.pid).orElseThrow()
            watch(fixtures.address, components, "idle tree, nothing watched", null)
            watch(fixtures.address, components, "push (observers, 1 s heartbeats)", EventOptions(WatchMode.PUSH))
            watch(
                fixtures.address,
                components,
                "poll at 10 Hz",
                EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds),
            )
        }
    }

    private suspend fun watch(address: String, components: ProcessHandle, label: String, watching: EventOptions?) {
        RtcTree(TreeConfig(listOf(address))).use { tree ->
            tree.refresh()
            val nodes = tree.find { it is ComponentNode }.toList()
            val subscriptions =
                watching
                    ?.let { options ->
                        coroutineScope {
                            nodes
                                .map { node -> async { tree.on(node, StateChanged::class.java, options) {} } }
                                .awaitAll()
                        }
                    }
                    .orEmpty()
            delay(options.monitoringWarmup)
            val missedBefore = tree.missedPollTicks
            val cpu = mutableListOf<Double>()
            val fixturesCpu = mutableListOf<Double>()
            val heap = mutableListOf<Double>()
            var cpuBefore = os.processCpuTime
            var fixturesBefore = cpuNanos(components)
            var before = System.nanoTime()
            repeat(options.monitoringWindow.inWholeSeconds.toInt().coerceAtLeast(1)) {
                delay(1.seconds)
                val cpuNow = os.processCpuTime
                val fixturesNow = cpuNanos(components)
                val now = System.nanoTime()
                cpu += 100.0 * (cpuNow - cpuBefore) / (now - before)
                fixturesCpu += 100.0 * (fixturesNow - fixturesBefore) / (now - before)
                heap += Heap.used() / Heap.MB
                cpuBefore = cpuNow
                fixturesBefore = fixturesNow
                before = now
            }
            val missed = tree.missedPollTicks - missedBefore
            val live = Heap.live() / Heap.MB
            subscriptions.forEach { it.cancel() }
            val cpuSamples = Samples(cpu, "% core")
            val target =
                when (watching?.mode) {
                    null -> ""
                    WatchMode.POLL -> "; target: under 30% of one core"
                    else -> "; target: under 5% of one core"
                }
            report.row(
                "$label: CPU",
                cpuSamples,
                "mean ${figure(cpu.average())}% of one core, per-second samples$target",
            )
            report.row(
                "$label: fixtures' CPU",
                Samples(fixturesCpu, "% core"),
                "mean ${figure(fixturesCpu.average())}% of one core: the ${nodes.size} components answering, in their own JVM",
            )
            report.row("$label: heap used", Samples(heap, "MB"), "live after GC ${figure(live)} MB")
            if (watching?.mode == WatchMode.POLL) {
                val ticks =
                    nodes.size *
                        (options.monitoringWindow.inWholeMilliseconds / watching.pollPeriod.inWholeMilliseconds)
                // Ticks that queued up before the window are counted when served, inside it.
                val backlog = if (missed > ticks) " (and ticks queued before it)" else ""
                report.value(
                    "$label: missed ticks",
                    missed.toDouble(),
                    "ticks",
                    "of about $ticks due in the window$backlog; target: none",
                )
                // Missed ticks are spread evenly over the components (the tree degrades evenly): this is each one's
                // rate.
                val achieved =
                    (ticks - missed).coerceAtLeast(0) / nodes.size.toDouble() / options.monitoringWindow.inWholeSeconds
                report.value("$label: rate achieved", achieved, "Hz", "reads of each component per second (10 asked)")
            }
        }
    }
}
