package org.rtcoord.bench

import java.lang.management.ManagementFactory

/**
 * A run of the chosen benchmarks, one after another (never two at once: each would be the other's load), into one
 * [Report]. A benchmark that fails is reported as failed and the run goes on.
 */
internal class Bench(private val options: BenchOptions, private val installation: Installation) {
    private val os = ManagementFactory.getOperatingSystemMXBean()

    suspend fun run(): Report {
        val report = Report()
        val loadBefore = os.systemLoadAverage
        val started = System.nanoTime()
        for (benchmark in options.benchmarks) {
            try {
                when (benchmark) {
                    Benchmark.MICRO -> MicroBench(options, report).run()
                    Benchmark.DISCOVERY -> DiscoveryBench(options, installation, report).run()
                    Benchmark.REACTION -> ReactionBench(options, report).run()
                    Benchmark.MONITORING -> MonitoringBench(options, report).run()
                    Benchmark.ROUNDTRIP -> RoundTripBench(options, installation, report).run()
                    Benchmark.MEMORY -> MemoryBench(options, report).run()
                    Benchmark.STARTUP -> StartupBench(options, installation, report).run()
                    Benchmark.PROFILE -> ProfileBench(options, installation, report).run()
                    Benchmark.DATA -> {
                        DataBench(options, report).run()
                        SimulatedPortBench(options, installation, report).run()
                    }
                    Benchmark.TEST -> TestBench(options, installation, report).run()
                    Benchmark.SIMULATION -> SimulationBench(options, installation, report).run()
                    Benchmark.EXPLORE -> ExploreBench(options, installation, report).run()
                    Benchmark.LOGS -> LogsBench(options, report).run()
                }
            } catch (e: Exception) {
                report.skipped(benchmark.label, "failed: ${e.message ?: e.javaClass.simpleName}")
            }
        }
        val minutes = (System.nanoTime() - started) / 60e9
        report.note(
            "${options.profile} run in ${figure(minutes)} min, seed ${options.seed}; ${os.availableProcessors} cores, load average " +
                "${figure(loadBefore)} before and ${figure(os.systemLoadAverage)} after; Java ${System.getProperty("java.version")}. " +
                "A loaded machine makes every figure slower and noisier, rtcoord's and the peers' alike."
        )
        val jvmOptions = ManagementFactory.getRuntimeMXBean().inputArguments.filter { it.startsWith("-XX:") }
        report.note(
            if (jvmOptions.isEmpty()) "JVM: the JDK's default options."
            else "JVM options: ${jvmOptions.joinToString(" ")}."
        )
        report.note("ratios compare medians measured in this run; nothing is asserted, nothing is stored.")
        return report
    }
}
