package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.DurationUnit
import kotlinx.coroutines.delay
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.datatypes.DataCodec
import org.rtcoord.datatypes.MadeUpValues
import org.rtcoord.datatypes.StandardDataTypes
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
 * writes, less the same process with the component inactive (its execution context still ticking), once the JIT has
 * compiled the write path: its compiler threads are what a JVM spends warming up, not what the port costs as it runs.
 * Writing and inactive windows alternate, and each pair gives one cost: the machine moves a window's CPU by a quarter
 * of what is measured, so one pair says little. After each pair, the [LoopbackFloor]'s: what the same bytes cost with
 * no CORBA and nothing made up, so that the row says how far over this machine's floor the port is at that moment (the
 * machine has moved both by half between runs an hour apart).
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
                val warmUp = simulation.warmUp(options.dataWindow, options.portWarmUpWindows)
                val writing = mutableListOf<Double>()
                val inactive = mutableListOf<Double>()
                val rates = mutableListOf<Double>()
                val floor = mutableListOf<Double>()
                LoopbackFloor(sampleBytes, PERIOD_MILLIS).use { loopback ->
                    repeat(options.portRounds) { round ->
                        if (round > 0) {
                            ranger.activate()
                            delay(options.dataWindow / 2)
                        }
                        val samplesBefore = received.get()
                        writing += simulation.cpuPerSecond(options.dataWindow) * 100
                        rates += (received.get() - samplesBefore) / options.dataWindow.toDouble(DurationUnit.SECONDS)
                        ranger.deactivate()
                        delay(options.dataWindow / 2)
                        inactive += simulation.cpuPerSecond(options.dataWindow) * 100
                        // The floor's pair right after the port's, the machine as it was for the port.
                        loopback.writing(true)
                        delay(options.dataWindow / 2)
                        val floorWriting = loopback.cpuPerSecond(options.dataWindow) * 100
                        loopback.writing(false)
                        delay(options.dataWindow / 2)
                        floor += floorWriting - loopback.cpuPerSecond(options.dataWindow) * 100
                    }
                }
                if (rates.any { it == 0.0 }) return report.skipped(LABEL, "no sample reached the tap")
                val cost = Samples(writing.zip(inactive) { w, i -> w - i }, "% of a core")
                val floorCost = Samples(floor, "% of a core")
                val overFloor =
                    if (floorCost.median > 0) "${figure(cost.median / floorCost.median)}x the loopback floor below"
                    else "the loopback floor below too small to compare with"
                report.row(
                    LABEL,
                    cost,
                    "made up and encoded in `rtcoord sim`, pushed to a tap in another process " +
                        "(${figure(Samples(rates, "/s").median)} samples/s reached it); " +
                        "${options.portRounds} pairs of ${options.dataWindow} windows, the process writing then inactive " +
                        "(medians ${figure(Samples(writing, "%").median)} and ${figure(Samples(inactive, "%").median)} %), " +
                        "after $warmUp; $overFloor; " +
                        "target under 1 %",
                )
                report.row(
                    FLOOR_LABEL,
                    floorCost,
                    "a JVM of its own (${LoopbackFloor.JVM_OPTIONS.joinToString(" ")}) writing $sampleBytes bytes " +
                        "every $PERIOD_MILLIS ms, answered with ${LoopbackFloor.REPLY_BYTES} bytes from another " +
                        "process; writing less idle, each pair right after one of the port's",
                )
            } finally {
                tap.cancel()
            }
        }
    }

    /** The bytes of one made-up RangeData sample as its port sends them. */
    private val sampleBytes: Int by lazy {
        val type = checkNotNull(StandardDataTypes.named("RangeData"))
        DataCodec(type).encode(MadeUpValues(type, 0).at(0), littleEndian = true).size
    }

    /** `./rtcoord sim FILE` with its console open (an empty stdin would end it), until closed. */
    private inner class Simulation(file: String) : AutoCloseable {
        private val process =
            ProcessBuilder(installation.launcher.toString(), "sim", file)
                .directory(installation.root.toFile())
                .redirectErrorStream(true)
                .apply { environment().keys.removeAll(TimedCommand.IGNORED_VARIABLES) }
                .start()
        private val lines = linesOf(process, "bench-sim-output")

        /** The `host:port` of the simulation's naming service. */
        val naming: String

        init {
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

        /**
         * Waits while the component writes until the JIT is quiet: at least three [window]s, then until its compiler
         * threads spent under 1 % of [QUIET_WINDOWS] windows in a row, at most [most] windows. C2 compiles a method
         * called once a period after thousands of periods, in waves tens of seconds apart at 100 Hz. Says how long it
         * took; where the compiler threads cannot be read (`/proc`), or [most] is three, three windows.
         */
        suspend fun warmUp(window: Duration, most: Int): String {
            delay(window * 3)
            var windows = 3
            fun seconds() = figure(window.toDouble(DurationUnit.SECONDS) * windows)
            if (most <= windows) return "${seconds()} s of warm-up"
            var compiled = compilerCpu() ?: return "${seconds()} s of warm-up (the JIT cannot be watched here)"
            var quiet = 0
            while (quiet < QUIET_WINDOWS && windows < most) {
                val start = System.nanoTime()
                delay(window)
                windows++
                val now = compilerCpu() ?: compiled
                quiet = if (now - compiled < (System.nanoTime() - start) / 100) quiet + 1 else 0
                compiled = now
            }
            return if (quiet < QUIET_WINDOWS) "${seconds()} s of warm-up, the JIT still compiling"
            else "${seconds()} s of warm-up, until the JIT was quiet"
        }

        /**
         * The CPU time (ns) of the JIT's compiler threads (`C1 CompilerThread0`, `C2 CompilerThread0`, ...) in the
         * launcher's JVM, read from `/proc`; null where it cannot be.
         */
        private fun compilerCpu(): Long? =
            processes().sumOf { handle ->
                val threads = Path.of("/proc/${handle.pid()}/task")
                if (!Files.isDirectory(threads)) return null
                Files.list(threads).use { all -> all.toList().filter(::isCompiler).sumOf(::threadCpu) }
            }

        private fun isCompiler(thread: Path): Boolean =
            COMPILER.matches(runCatching { Files.readString(thread.resolve("comm")).trim() }.getOrDefault(""))

        /** A thread's user and system time from its `stat` (fields 14 and 15, in ticks); 0 once it has ended. */
        private fun threadCpu(thread: Path): Long = runCatching {
            val fields = Files.readString(thread.resolve("stat")).substringAfterLast(')').trim().split(' ')
            (fields[11].toLong() + fields[12].toLong()) * NANOS_PER_TICK
        }
            .getOrDefault(0L)

        /** The process's CPU time per second of wall time over [window]. */
        suspend fun cpuPerSecond(window: Duration): Double = cpuPerSecond(window, ::processes)

        /** The launcher and the JVM it starts (as a child when it makes its class archive). */
        private fun processes(): Sequence<ProcessHandle> =
            sequenceOf(process.toHandle()) + process.toHandle().descendants().iterator().asSequence()

        override fun close() {
            process.outputStream.close()
            if (!process.waitFor(10, TimeUnit.SECONDS)) process.destroyForcibly().waitFor()
        }
    }

    private companion object {
        const val LABEL = "simulated RangeData(1081) out-port at 100 Hz, rtcoord sim"
        const val FLOOR_LABEL = "loopback floor: a sample's bytes at 100 Hz, no CORBA"
        const val PERIOD_MILLIS = 10L
        const val QUIET_WINDOWS = 3

        /** Linux counts a thread's CPU in `/proc` in ticks of USER_HZ, 100 a second. */
        const val NANOS_PER_TICK = 10_000_000L
        val COMPILER = Regex("C[12] CompilerThre.*")
        val ranger =
            ComponentType(
                "ranger",
                listOf(PortSpec.DataOut("range", DataType.of("IDL:RTC/RangeData:1.0")!!)),
                rate = 100.0,
            )
    }
}
