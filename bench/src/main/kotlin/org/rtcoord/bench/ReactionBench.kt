package org.rtcoord.bench

import RTC.ReturnCode_t
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.withTimeout
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.FixtureComponent
import org.rtcoord.fixtures.FixtureRuntime
import org.rtcoord.fixtures.Scenarios
import org.rtcoord.fixtures.naming.NamingService
import org.rtcoord.fixtures.rtSystem
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.microseconds
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * Reaction latency: from a component's state change (timestamped by the fixture, in this JVM, just
 * before it changes state) to the start of the [StateChanged] callback. Push: one component, changes one
 * after another with short random pauses. Poll at 10 Hz: ten components changing independently, each
 * after a random pause within one period, so changes fall on every phase of the poll tick.
 */
internal class ReactionBench(private val options: BenchOptions, private val report: Report) {
    suspend fun run() {
        NamingService.start().use { naming ->
            rtSystem(naming.corbaloc) {
                component(Scenarios.relay, "push0")
                repeat(POLLED) { component(Scenarios.relay, "poll$it") }
            }.use { system ->
                RtcTree.create(TreeConfig(listOf(naming.address))).use { tree ->
                    val context = "/${naming.address}/${FixtureRuntime.hostContext}"
                    report.section("reaction: state change to callback start, ${options.reactionChanges} changes each (fixtures in the bench JVM)")
                    // Warmed up first, as every timed quantity here: the JIT compiles the path the timed changes take.
                    changes(tree, "$context/push0.rtc", system.component("push0"), EventOptions(WatchMode.PUSH), options.reactionChanges / 5, 10.milliseconds, Random(options.seed))
                    val push = changes(tree, "$context/push0.rtc", system.component("push0"), EventOptions(WatchMode.PUSH), options.reactionChanges, 10.milliseconds, Random(options.seed))
                    val all = Samples.millis(push.map { it.nanos })
                    report.row("push (ComponentObserver)", all, "p99 ${figure(all.percentile(99.0))} ms; target: p99 under 5 ms")
                    // Half the changes are deactivations, held on purpose: shown apart, each kind's tail is its own.
                    for ((state, note) in listOf(LifeCycle.ACTIVE to "", LifeCycle.INACTIVE to "; held at least 10 ms, to tell an abort from a deactivation")) {
                        val kind = Samples.millis(push.filter { it.to == state }.map { it.nanos })
                        report.row("push, changes to $state only", kind, "p99 ${figure(kind.percentile(99.0))} ms$note")
                    }
                    val period = 100.milliseconds
                    val poll = coroutineScope {
                        (0 until POLLED).map { index ->
                            async {
                                changes(
                                    tree, "$context/poll$index.rtc", system.component("poll$index"), EventOptions(WatchMode.POLL, pollPeriod = period),
                                    options.reactionChanges / POLLED, period, Random(options.seed + 1 + index),
                                )
                            }
                        }.awaitAll().flatten().map { it.nanos }
                    }
                    report.row("poll at 10 Hz", Samples.millis(poll), "p99 ${figure(Samples.millis(poll).percentile(99.0))} ms; target: within 102 ms (one period + 2 ms)")
                }
            }
        }
    }

    /**
     * Changes [fixture]'s state [count] times, each after a pause up to [maxPause], watching it at [path]
     * as [watching] says; returns each change's reaction.
     */
    private suspend fun changes(
        tree: RtcTree,
        path: String,
        fixture: FixtureComponent,
        watching: EventOptions,
        count: Int,
        maxPause: Duration,
        random: Random,
    ): List<Reaction> {
        val arrivals = Channel<Pair<StateChanged, Long>>(Channel.UNLIMITED)
        val subscription = tree.on(path, StateChanged::class.java, watching) { event -> arrivals.trySend(event to System.nanoTime()) }
        try {
            var active = fixture.state == RTC.LifeCycleState.ACTIVE_STATE
            return List(count) {
                delay(random.nextLong(maxPause.inWholeMicroseconds).microseconds)
                val target = if (active) LifeCycle.INACTIVE else LifeCycle.ACTIVE
                val changed = System.nanoTime()
                val code = if (active) fixture.deactivate() else fixture.activate()
                check(code == ReturnCode_t.RTC_OK) { "${fixture.instanceName}: changing to $target failed" }
                active = !active
                val noticed = withTimeout(5.seconds) {
                    var arrival = arrivals.receive()
                    while (arrival.first.new != target) arrival = arrivals.receive()
                    arrival.second
                }
                Reaction(target, noticed - changed)
            }
        } finally {
            subscription.cancel()
        }
    }

    /** A change to [to], noticed [nanos] after it was made. */
    private class Reaction(val to: LifeCycle, val nanos: Long)

    private companion object {
        const val POLLED = 10
    }
}
