package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runInterruptible
import org.openjdk.jmh.runner.Runner
import org.openjdk.jmh.runner.options.OptionsBuilder
import org.openjdk.jmh.runner.options.TimeValue
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.bench.jmh.RemoteCallBenchmark
import org.rtcoord.fixtures.FixtureProcess

/**
 * The cost of one remote call and one notification ([RemoteCallBenchmark], JMH in a JVM of its own): time per call, and
 * the CPU each side spends on it, the coordinator's and the component's. Ten relays in a fixture JVM answer the reads;
 * a tree in this JVM watches one of them by push, and its observer receives the notifications the benchmark sends.
 * JMH's own report goes to `bench/target/jmh.txt`.
 */
internal class MicroBench(private val options: BenchOptions, private val report: Report) {
    suspend fun run() {
        FixtureProcess.start("--scenario", "scale:10").use { fixtures ->
            RtcTree(TreeConfig(listOf(fixtures.address))).use { tree ->
                tree.refresh()
                val node = tree.find { it is ComponentNode }.toList().first()
                val subscription = tree.on(node, StateChanged::class.java, EventOptions(WatchMode.PUSH)) {}
                val cpu = Files.createTempFile("rtcoord-micro", ".txt")
                try {
                    val (warmups, measured) = options.microIterations
                    val jmh =
                        OptionsBuilder()
                            .include(RemoteCallBenchmark::class.java.name.replace(".", "\\.") + "\\.")
                            .forks(1)
                            .warmupIterations(warmups)
                            .warmupTime(TimeValue.milliseconds(options.microIteration.inWholeMilliseconds))
                            .measurementIterations(measured)
                            .measurementTime(TimeValue.milliseconds(options.microIteration.inWholeMilliseconds))
                            // Only these: not the bench JVM's flags, which would load an agent the environment gives
                            // (JAVA_TOOL_OPTIONS) twice.
                            .jvmArgs(
                                "-Drtcoord.bench.naming=${fixtures.address}",
                                "-Drtcoord.bench.component=${node.path.names.joinToString("/")}",
                                "-Drtcoord.bench.fixtures.pid=${fixtures.pid}",
                                "-Drtcoord.bench.cpu=$cpu",
                            )
                            .output(jmhOutput().toString())
                            .build()
                    report.section(
                        "one call and one notification (JMH, ${options.microIterations.second} x ${options.microIteration} measured; coordinator and component CPU are their processes')"
                    )
                    val results = runInterruptible(Dispatchers.IO) { Runner(jmh).run() }
                    if (results.isEmpty() || results.any { it.benchmarkResults.isEmpty() }) {
                        report.skipped("microbenchmarks", "failed: see ${jmhOutput()}")
                        return
                    }
                    val costs =
                        Files.readAllLines(cpu)
                            .map { it.split(' ') }
                            .groupBy({ it[0] }, { it[1].toDouble() / 1e3 to it[2].toDouble() / 1e3 })
                    for (result in
                        results.sortedBy { LABELS.keys.indexOf(it.params.benchmark.substringAfterLast('.')) }) {
                        val name = result.params.benchmark.substringAfterLast('.')
                        val label = LABELS[name] ?: name
                        val times =
                            result.benchmarkResults.flatMap { it.iterationResults }.map { it.primaryResult.score }
                        report.row(
                            "$label: time per call",
                            Samples(times, "us"),
                            if (name == "notification") "the sender's, paced by the receiver" else "",
                        )
                        val perCall = costs[name].orEmpty()
                        if (perCall.isEmpty()) continue
                        report.row(
                            "$label: coordinator CPU",
                            Samples(perCall.map { it.first }, "us"),
                            "per call, ${if (name == "notification") "the tree receiving" else "the caller"}",
                        )
                        report.row(
                            "$label: component CPU",
                            Samples(perCall.map { it.second }, "us"),
                            "per call, ${if (name == "notification") "the sender" else "the fixture JVM answering"}",
                        )
                    }
                } finally {
                    subscription.cancel()
                    Files.deleteIfExists(cpu)
                }
            }
        }
    }

    private fun jmhOutput(): Path = Paths.get(System.getProperty("rtcoord.root", "."), "bench", "target", "jmh.txt")

    private companion object {
        val LABELS =
            linkedMapOf(
                "stateRead" to "one state read (get_component_state)",
                "profileRead" to "one profile read (get_component_profile)",
                "notification" to "one notification (update_status heartbeat)",
            )
    }
}
