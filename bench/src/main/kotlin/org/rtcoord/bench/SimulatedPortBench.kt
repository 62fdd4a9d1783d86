package org.rtcoord.bench

import java.nio.file.Files
import java.time.Duration as JavaDuration
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.DurationUnit
import kotlinx.coroutines.delay
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.DataType
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.rtSystem

/**
 * What `rtcoord sim` spends on one simulated out-port of `RangeData` (1081 ranges) at 100 Hz: the saved system of that
 * one component runs in `./rtcoord sim`, its own process, as a user runs it; this JVM's tree taps the port, so the
 * reader's receipt and decoding are not the simulation's cost. The cost is the process's CPU while the component
 * writes, less the same process with the component inactive (its execution context still ticking), after a warm-up long
 * enough for the JIT to compile the write path.
 */
internal class SimulatedPortBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    suspend fun run() {
        installation.cliMissing?.let {
            return report.skipped(LABEL, it)
        }
        val file = Files.createTempFile("bench-ranger", ".xml")
        try {
            Files.writeString(file, RtsProfiles.write(saved(), ProfileFormat.XML))
            Simulation(file.toString()).use { simulation -> measure(simulation) }
        } finally {
            Files.deleteIfExists(file)
        }
    }

    private suspend fun saved() =
        NamingService.start().use { naming ->
            rtSystem(naming.corbaloc) { component(ranger, "ranger0") }
                .use {
                    RtcTree(TreeConfig(listOf(naming.address))).use { SystemProfiles(it).save() }
                }
        }

    private suspend fun measure(simulation: Simulation) {
        RtcTree(TreeConfig(listOf(simulation.naming))).use { tree ->
            val ranger = tree.component("/${simulation.naming}/${RuntimeProcess.hostContext}/ranger0.rtc")
            val received = AtomicLong()
            val tap = tree.port("${ranger.path}:range").tap { received.incrementAndGet() }
            try {
                delay(options.dataWindow * 3) // warm-up: the JIT compiles the write path
                val samplesBefore = received.get()
                val writing = simulation.cpuPerSecond(options.dataWindow)
                val rate = (received.get() - samplesBefore) / options.dataWindow.toDouble(DurationUnit.SECONDS)
                ranger.deactivate()
                delay(options.dataWindow / 2)
                val idle = simulation.cpuPerSecond(options.dataWindow)
                if (rate == 0.0) return report.skipped(LABEL, "no sample reached the tap")
                report.value(
                    LABEL,
                    (writing - idle) * 100,
                    "% of a core",
                    "made up and encoded in `rtcoord sim`, pushed to a tap in another process (${figure(rate)} samples/s reached it); " +
                        "the process ${figure(writing * 100)} % writing, ${figure(idle * 100)} % inactive; target under 1 %",
                )
            } finally {
                tap.cancel()
            }
        }
    }

    /** `./rtcoord sim FILE` with its console open (an empty stdin would end it), until closed. */
    private inner class Simulation(file: String) : AutoCloseable {
        private val process =
            ProcessBuilder(installation.launcher.toString(), "sim", file)
                .directory(installation.root.toFile())
                .redirectErrorStream(true)
                .apply { environment().keys.removeAll(TimedCommand.IGNORED_VARIABLES) }
                .start()
        private val lines = LinkedBlockingQueue<String>()

        /** The `host:port` of the simulation's naming service. */
        val naming: String

        init {
            Thread({ process.inputStream.bufferedReader().forEachLine { lines += it } }, "bench-sim-output").apply {
                isDaemon = true
                start()
            }
            naming =
                try {
                    awaitReady()
                } catch (e: Exception) {
                    process.destroyForcibly()
                    throw e
                }
        }

        /** The naming address the simulation prints before its `ready` line. */
        private fun awaitReady(): String {
            var address: String? = null
            while (true) {
                val line = lines.poll(60, TimeUnit.SECONDS) ?: error("rtcoord sim printed nothing for 60 s")
                if (line.startsWith("naming ")) address = line.removePrefix("naming ")
                if (line.startsWith("ready "))
                    return checkNotNull(address) { "rtcoord sim said ready without its naming address" }
            }
        }

        /** The process's CPU time per second of wall time over [window]. */
        suspend fun cpuPerSecond(window: Duration): Double {
            val before = cpu()
            val start = System.nanoTime()
            delay(window)
            return (cpu() - before).toDouble() / (System.nanoTime() - start)
        }

        /** The CPU time of the launcher and the JVM it starts (as a child when it makes its class archive). */
        private fun cpu(): Long =
            (sequenceOf(process.toHandle()) + process.toHandle().descendants().iterator().asSequence()).sumOf { handle
                ->
                handle.info().totalCpuDuration().map(JavaDuration::toNanos).orElseThrow {
                    IllegalStateException("the CPU time of rtcoord sim (pid ${handle.pid()}) cannot be read")
                }
            }

        override fun close() {
            process.outputStream.close()
            if (!process.waitFor(10, TimeUnit.SECONDS)) process.destroyForcibly().waitFor()
        }
    }

    private companion object {
        const val LABEL = "simulated RangeData(1081) out-port at 100 Hz, rtcoord sim"
        val ranger =
            ComponentType(
                "ranger",
                listOf(PortSpec.DataOut("range", DataType.of("IDL:RTC/RangeData:1.0")!!)),
                rate = 100.0,
            )
    }
}
