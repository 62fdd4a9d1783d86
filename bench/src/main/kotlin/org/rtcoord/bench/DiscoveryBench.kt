package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption
import kotlin.time.Duration.Companion.minutes
import kotlinx.coroutines.flow.toList
import org.rtcoord.ComponentNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.FixtureProcess

/**
 * Discovery of a whole system of N relay components (three ports each, in nested naming contexts) served by a fixture
 * JVM of its own: `rtcoord ls -l -R` against rtshell's `rtls -l -R` as whole processes, and the library (a fresh
 * [RtcTree] reading every component in a warm JVM) against a warm Python building rtctree's `RTCTree` of the same
 * system. Then the floor: what N profile reads cost at the loopback round trip and the concurrency this machine
 * achieves.
 */
internal class DiscoveryBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    private val library = sortedMapOf<Int, Samples>()

    suspend fun run() {
        var floor: DiscoveryFloor? = null
        for (n in options.discoverySizes) {
            FixtureProcess.start("--scenario", "scale:$n", timeout = 10.minutes).use { fixtures ->
                report.section("discovery, whole process, N=$n (fixtures in a separate JVM)")
                processes(n, fixtures.address)
                report.section("discovery, library in a warm JVM, N=$n")
                library(n, fixtures.address)
                if (n == options.discoverySizes.last())
                    floor = DiscoveryFloor.measure(fixtures.address, options.floorCalls)
            }
        }
        floor?.let(::reportFloor)
    }

    private fun processes(n: Int, address: String) {
        val rtls = installation.peer("rtls")
        val commands = buildList {
            installation.cliMissing?.let { report.skipped(RTCOORD_LS, it) }
                ?: add(
                    TimedCommand(
                        RTCOORD_LS,
                        listOf(installation.launcher.toString(), "ls", "-l", "-R", "/$address/"),
                        installation.root,
                    )
                )
            rtls?.let { add(TimedCommand(RTLS, listOf(it.toString(), "-l", "-R", "/$address/"), installation.root)) }
                ?: report.skipped(RTLS, installation.peerMissing("rtls"))
        }
        if (commands.isEmpty()) return
        // A component that does not answer within a tool's deadline is listed as a zombie, or not at all.
        val incomplete = mutableMapOf<String, MutableList<Int>>()
        val times =
            timeInterleaved(commands, options.processWarmups, options.processRepetitions(n)) { command, run ->
                val listed =
                    run.output.count { line ->
                        line.trim().substringAfterLast(' ').let { !it.startsWith("*") && it.endsWith(".rtc") }
                    }
                if (listed != n) incomplete.getOrPut(command.label) { mutableListOf() } += listed
            }
        fun notes(label: String, vararg more: String?): String =
            (more.toList() +
                    incomplete[label]?.let { "listed only ${it.joinToString()} of $n components in ${it.size} runs" })
                .filterNotNull()
                .joinToString("; ")
        val byLabel = commands.map { it.label }.zip(times).toMap()
        val ours = byLabel[RTCOORD_LS]
        val theirs = byLabel[RTLS]
        ours?.let {
            report.row(
                RTCOORD_LS,
                it,
                notes(RTCOORD_LS, theirs?.let { peer -> speedup(it, peer, "rtls") }, processTarget(n)),
            )
        }
        theirs?.let { report.row(RTLS, it, notes(RTLS)) }
    }

    private fun processTarget(n: Int): String? =
        when {
            n <= 10 -> "target: no slower than 1.2x rtls"
            n >= 1000 -> "target: at least 3x faster than rtls"
            else -> null
        }

    private suspend fun library(n: Int, address: String) {
        val warmed =
            JitWarmUp(round = (WARM_UP_ROUND / n).coerceAtLeast(1), limit = options.libraryWarmUpLimit / n).make {
                discover(n, address)
            }
        val timed = JitCompilation.during { List(options.libraryRepetitions) { discover(n, address) } }
        val runs = timed.value
        val jit =
            "warm-up $warmed discoveries; then the JIT compiled for ${timed.compiledMillis ?: "?"} ms of the ${figure(timed.millis / 1000.0)} s timed"
        val ours = Samples.seconds(runs.map { it.total })
        val refreshOnly = Samples.seconds(runs.map { it.refresh })
        library[n] = ours
        val incomplete = runs.map { it.complete }.filter { it < n }
        val missing =
            if (incomplete.isEmpty()) ""
            else "; read only ${incomplete.joinToString()} of $n components completely in ${incomplete.size} runs"
        val python = installation.peer("python")
        if (python == null) {
            report.row(TREE_REFRESH, ours, "$jit$missing")
            report.row(REFRESH_ONLY, refreshOnly)
            report.skipped("rtctree", installation.peerMissing("python"))
            return
        }
        val (constructed, full) = rtctree(python, n, address)
        val target = if (n >= 1000) "; target: at least 10x faster than rtctree" else ""
        report.row(
            TREE_REFRESH,
            ours,
            "${speedup(ours, full, "rtctree reading the same")}; ${speedup(ours, constructed, "RTCTree() alone")}$target; $jit$missing",
        )
        report.row(
            REFRESH_ONLY,
            refreshOnly,
            "the same runs without creating the tree (its ORB); ${speedup(refreshOnly, full, "rtctree reading the same")}",
        )
        report.row("rtctree RTCTree() + ports, contexts, states", full, "the same information as rtcoord's snapshots")
        report.row("rtctree RTCTree() alone", constructed, "what rtctree reads on construction: contexts, profiles")
    }

    /**
     * One library discovery: nanoseconds in all and in the refresh alone, and how many components it read completely.
     */
    private class Discovery(val total: Long, val refresh: Long, val complete: Int)

    /** A fresh tree over the system, every component read (profile, ports, contexts, states). */
    private suspend fun discover(n: Int, address: String): Discovery {
        val start = System.nanoTime()
        val tree = RtcTree(TreeConfig(listOf(address)))
        try {
            val created = System.nanoTime()
            tree.refresh()
            val done = System.nanoTime()
            val complete =
                tree
                    .find { it is ComponentNode }
                    .toList()
                    .count { (it as ComponentNode).snapshots.value?.ports?.size == 3 }
            check(complete > 0 || n == 0) { "discovery read none of the $n components" }
            return Discovery(done - start, done - created, complete)
        } finally {
            tree.close()
        }
    }

    /** rtctree's times in its own warm Python process: construction alone, and with everything read. */
    private fun rtctree(python: Path, n: Int, address: String): Pair<Samples, Samples> {
        val script = Files.createTempFile("rtctree_discovery", ".py")
        try {
            DiscoveryBench::class.java.getResourceAsStream("rtctree_discovery.py")!!.use {
                Files.copy(it, script, StandardCopyOption.REPLACE_EXISTING)
            }
            val command =
                listOf(
                    python.toString(),
                    script.toString(),
                    address,
                    options.libraryWarmups.toString(),
                    options.libraryRepetitions.toString(),
                )
            val reps =
                TimedCommand("rtctree", command, installation.root)
                    .run()
                    .output
                    .filter { it.startsWith("rep ") }
                    .map { it.split(' ') }
            check(reps.size == options.libraryRepetitions) {
                "rtctree printed ${reps.size} repetitions, not ${options.libraryRepetitions}"
            }
            reps.forEach { check(it[3].toInt() == n) { "rtctree found ${it[3]} components, not $n" } }
            return Samples(reps.map { it[1].toDouble() }, "s") to Samples(reps.map { it[2].toDouble() }, "s")
        } finally {
            Files.deleteIfExists(script)
        }
    }

    private fun reportFloor(floor: DiscoveryFloor) {
        report.section("discovery floor: N x loopback round trip of one profile read / achieved concurrency")
        report.row("get_component_profile round trip, one at a time", floor.roundTrip)
        report.value(
            "achieved concurrency (${floor.threads} callers)",
            floor.concurrency,
            "calls",
            "${figure(floor.callsPerSecond)} profile reads/s; target: at least 1.5",
        )
        val single = floor.byCallers.getValue(1)
        for ((callers, perSecond) in floor.byCallers) {
            report.value(
                "profile reads/s, $callers callers",
                perSecond,
                "calls/s",
                "${figure(perSecond / single)}x one caller",
            )
        }
        for ((n, measured) in library) {
            val estimate = floor.estimate(n)
            report.value(
                "floor N=$n",
                estimate * 1000,
                "ms",
                "library median is ${figure(measured.median / estimate)}x the floor",
            )
        }
    }

    private companion object {
        const val RTCOORD_LS = "rtcoord ls -l -R"
        const val RTLS = "rtls -l -R"
        const val TREE_REFRESH = "rtcoord RtcTree.create + refresh"
        const val REFRESH_ONLY = "rtcoord refresh alone"

        /** Components read by a round of the library's warm-up: about a second of discoveries. */
        const val WARM_UP_ROUND = 500
    }
}
