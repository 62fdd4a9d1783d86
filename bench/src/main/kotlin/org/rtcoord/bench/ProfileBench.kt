package org.rtcoord.bench

import java.nio.file.Files
import kotlin.time.Duration.Companion.minutes
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles

/**
 * Restoring a whole system from its RTSProfile: N relays chained into one data flow (N - 1 connections, in nested
 * naming contexts) served by a fixture JVM of their own, saved once. Before each timed run every connection is removed;
 * `rtcoord profile restore` and rtshell's `rtresurrect` then make them again from the same file as whole processes,
 * interleaved, each checked to have restored the whole system. The library's restore in the warm bench JVM is timed the
 * same way for reference.
 */
internal class ProfileBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    suspend fun run() {
        val n = options.profileSize
        FixtureProcess.start("--scenario", "pipeline:$n", timeout = 10.minutes).use { fixtures ->
            RtcTree(TreeConfig(listOf(fixtures.address))).use { tree ->
                val profiles = SystemProfiles(tree)
                val saved = profiles.save()
                check(saved.components.size == n && saved.dataPortConnectors.size == n - 1) {
                    "saved ${saved.components.size} components and ${saved.dataPortConnectors.size} connections, not $n and ${n - 1}"
                }
                val file = Files.createTempFile("bench-profile", ".xml")
                try {
                    Files.writeString(file, RtsProfiles.write(saved, ProfileFormat.XML))
                    report.section("profile restore, N=$n, ${n - 1} connections (fixtures in a separate JVM)")
                    processes(profiles, saved, file.toString())
                    library(profiles, saved)
                } finally {
                    Files.deleteIfExists(file)
                }
            }
        }
    }

    private suspend fun processes(profiles: SystemProfiles, saved: RtsProfile, file: String) {
        val rtresurrect = installation.peer("rtresurrect")
        val commands = buildList {
            installation.cliMissing?.let { report.skipped(RTCOORD_RESTORE, it) }
                ?: add(
                    TimedCommand(
                        RTCOORD_RESTORE,
                        listOf(installation.launcher.toString(), "profile", "restore", file),
                        installation.root,
                    )
                )
            rtresurrect?.let { add(TimedCommand(RTRESURRECT, listOf(it.toString(), file), installation.root)) }
                ?: report.skipped(RTRESURRECT, installation.peerMissing("rtresurrect"))
        }
        if (commands.isEmpty()) return
        val times = commands.associateWith { mutableListOf<Long>() }
        val incomplete = mutableMapOf<String, Int>()
        suspend fun once(command: TimedCommand): Long {
            disturb(profiles, saved)
            val nanos = command.run().nanos
            if (profiles.check(saved, state = null).isNotEmpty()) incomplete.merge(command.label, 1, Int::plus)
            return nanos
        }
        repeat(options.processWarmups) { commands.forEach { once(it) } }
        repeat(options.profileRepetitions) { commands.forEach { times.getValue(it) += once(it) } }
        val samples = times.mapKeys { it.key.label }.mapValues { Samples.seconds(it.value) }
        fun notes(label: String, vararg more: String?) =
            (more.toList() + incomplete[label]?.let { "left differences from the profile in $it runs" })
                .filterNotNull()
                .joinToString("; ")
        val theirs = samples[RTRESURRECT]
        samples[RTCOORD_RESTORE]?.let { ours ->
            report.row(RTCOORD_RESTORE, ours, notes(RTCOORD_RESTORE, theirs?.let { speedup(ours, it, "rtresurrect") }))
        }
        theirs?.let { report.row(RTRESURRECT, it, notes(RTRESURRECT, "the same file, the same system")) }
    }

    private suspend fun library(profiles: SystemProfiles, saved: RtsProfile) {
        val runs =
            List(options.profileRepetitions) {
                disturb(profiles, saved)
                val start = System.nanoTime()
                profiles.restore(saved)
                System.nanoTime() - start
            }
        report.row(
            "rtcoord SystemProfiles.restore in a warm JVM",
            Samples.seconds(runs),
            "the same restore without starting a process",
        )
    }

    /** Removes every connection the profile names, so that a restore has them all to make. */
    private suspend fun disturb(profiles: SystemProfiles, saved: RtsProfile) {
        val removed = profiles.teardown(saved).size
        check(removed == saved.dataPortConnectors.size) {
            "removed $removed connections, not ${saved.dataPortConnectors.size}"
        }
    }

    private companion object {
        const val RTCOORD_RESTORE = "rtcoord profile restore"
        const val RTRESURRECT = "rtresurrect"
    }
}
