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
import org.rtcoord.WatchMethod
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
        atScale()
    }

    /**
     * Push at scale (issue 54: "10,000 components watched by push: under 10% of a core; memory at most 8 KB per
     * component"): the live heap the tree and its subscriptions add, over the bench JVM's before the tree, per
     * component.
     */
    private suspend fun atScale() {
        val n = options.pushScaleComponents
        FixtureProcess.start("--scenario", "scale:$n", timeout = 10.minutes).use { fixtures ->
            report.section(
                "monitoring cost at scale: $n components watched by push for ${options.monitoringWindow}, after ${options.monitoringWarmup} warm-up"
            )
            val components = ProcessHandle.of(fixtures.pid).orElseThrow()
            val heapBefore = Heap.live()
            watch(fixtures.address, components, "push, $n components", EventOptions(WatchMode.PUSH), heapBefore)
        }
    }

    /** Waits, at most [SETTLE_LIMIT], until the tree watches all [count] components by push; reports how long. */
    private suspend fun settled(tree: RtcTree, label: String, count: Int) {
        val started = System.nanoTime()
        var pushed = 0
        while (System.nanoTime() - started < SETTLE_LIMIT.inWholeNanoseconds) {
            pushed = tree.snapshot().components.count { it.watchMethod is WatchMethod.Pushed }
            if (pushed >= count) break
            delay(1.seconds)
        }
        report.value(
            "$label: every observer attached after",
            (System.nanoTime() - started) / 1e9,
            "s",
            "$pushed of $count components watched by push when the warm-up began (at most ${SETTLE_LIMIT.inWholeMinutes} min waited)",
        )
    }

    /**
     * Watches every component of the system at [address] as [watching] says (null: only the tree) and reports the
     * window's CPU, both JVMs', and heap; with [heapBefore], also the live heap the tree adds per component.
     */
    private suspend fun watch(
        address: String,
        components: ProcessHandle,
        label: String,
        watching: EventOptions?,
        heapBefore: Long? = null,
    ) {
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
            // At scale attaching every observer takes a while: the window measures watching, not attaching.
            if (heapBefore != null) settled(tree, label, nodes.size)
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
            val heartbeats =
                tree.snapshot().components.mapNotNull { (it.watchMethod as? WatchMethod.Pushed)?.heartbeat }
            val liveBytes = if (heapBefore != null) Heap.kept() else Heap.live()
            val live = liveBytes / Heap.MB
            subscriptions.forEach { it.cancel() }
            val cpuSamples = Samples(cpu, "% core")
            val target =
                when {
                    watching == null -> ""
                    watching.mode == WatchMode.POLL -> "; target: under 30% of one core"
                    heapBefore != null -> "; target: under 10% of one core"
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
            if (heapBefore != null && heartbeats.isNotEmpty()) {
                val counts = heartbeats.groupingBy { it }.eachCount().entries.sortedBy { it.key }
                report.value(
                    "$label: observers' heartbeat",
                    heartbeats.sorted()[heartbeats.size / 2].inWholeMilliseconds / 1000.0,
                    "s",
                    "median; ${counts.joinToString { "${it.value} at ${it.key}" }}, ${watching?.heartbeat} asked (the tree's floor past 2500 components)",
                )
            }
            if (heapBefore != null) {
                report.value(
                    "$label: live heap per component",
                    (liveBytes - heapBefore) / 1024.0 / nodes.size,
                    "KB",
                    "the tree and its ${subscriptions.size} subscriptions, over the JVM's ${figure(heapBefore / Heap.MB)} MB before the tree; target: at most 8 KB",
                )
            }
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

    private companion object {
        /** The longest wait for every observer to be attached before the window. */
        val SETTLE_LIMIT = 5.minutes
    }
}
