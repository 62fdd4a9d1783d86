package org.rtcoord.bench

import RTC.ReturnCode_t
import kotlin.random.Random
import kotlin.time.Duration
import kotlin.time.Duration.Companion.microseconds
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
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
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.rtSystem

/**
 * Reaction latency: from a component's state change (timestamped by the fixture, in this JVM, just before it changes
 * state) to the start of the [StateChanged] callback. Push: one component, changes one after another with short random
 * pauses, as many of each kind as the poll makes in all. Poll at 10 Hz: ten components changing independently, each
 * after a random pause within one period, so changes fall on every phase of the poll tick.
 */
internal class ReactionBench(private val options: BenchOptions, private val report: Report) {
    suspend fun run() {
        NamingService.start().use { naming ->
            rtSystem(naming.corbaloc) {
                    component(pushed, "push0")
                    repeat(POLLED) { component(Scenarios.relay, "poll$it") }
                }
                .use { system ->
                    RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                        val context = "/${naming.address}/${RuntimeProcess.hostContext}"
                        // As many changes of each kind as the poll makes in all: a kind's p99 is then not the second
                        // largest of 200.
                        val pushChanges = options.reactionChanges * Kind.values().size
                        report.section(
                            "reaction: state change to callback start, $pushChanges changes by push, ${options.reactionChanges} by poll (fixtures in the bench JVM)"
                        )
                        // Warmed up first, as every timed quantity here, and until the JIT is quiet (JitWarmUp).
                        val warmUp =
                            JitWarmUp(round = (pushChanges / 8).coerceAtLeast(1), limit = options.reactionWarmUpLimit)
                        val timed =
                            changes(
                                tree,
                                "$context/push0.rtc",
                                system.component("push0"),
                                EventOptions(WatchMode.PUSH),
                                pushChanges,
                                10.milliseconds,
                                Random(options.seed),
                                aborts = true,
                                warmUp = warmUp,
                            )
                        val push = timed.reactions
                        val all = Samples.millis(push.map { it.nanos })
                        report.row(
                            "push (ComponentObserver)",
                            all,
                            "p99 ${figure(all.percentile(99.0))} ms; target: p99 under 5 ms for every kind; ${timed.jit}",
                        )
                        // Each kind's tail is its own: a deactivation is held until an abort's ERROR hint cannot be
                        // behind it.
                        for (kind in Kind.values()) {
                            val samples = Samples.millis(push.filter { it.kind == kind }.map { it.nanos })
                            report.row(
                                "push, ${kind.label} only",
                                samples,
                                "p99 ${figure(samples.percentile(99.0))} ms",
                            )
                        }
                        val period = 100.milliseconds
                        val poll = coroutineScope {
                            (0 until POLLED)
                                .map { index ->
                                    async {
                                        changes(
                                                tree,
                                                "$context/poll$index.rtc",
                                                system.component("poll$index"),
                                                EventOptions(WatchMode.POLL, pollPeriod = period),
                                                options.reactionChanges / POLLED,
                                                period,
                                                Random(options.seed + 1 + index),
                                            )
                                            .reactions
                                    }
                                }
                                .awaitAll()
                                .flatten()
                                .map { it.nanos }
                        }
                        report.row(
                            "poll at 10 Hz",
                            Samples.millis(poll),
                            "p99 ${figure(Samples.millis(poll).percentile(99.0))} ms; target: within 102 ms (one period + 2 ms)",
                        )
                    }
                }
        }
    }

    /**
     * Changes [fixture]'s state [count] times, each after a pause up to [maxPause], watching it at [path] as [watching]
     * says; returns each change's reaction. With [aborts], an active component is made to fail as often as it is
     * deactivated (then reset), timed from the fixture's record of the abort. With [warmUp], untimed changes come
     * first, under the same subscription as the timed ones.
     */
    private suspend fun changes(
        tree: RtcTree,
        path: String,
        fixture: RuntimeComponent,
        watching: EventOptions,
        count: Int,
        maxPause: Duration,
        random: Random,
        aborts: Boolean = false,
        warmUp: JitWarmUp? = null,
    ): Changes {
        val arrivals = Channel<Pair<StateChanged, Long>>(Channel.UNLIMITED)
        val subscription =
            tree.on(path, StateChanged::class.java, watching) { event -> arrivals.trySend(event to System.nanoTime()) }
        suspend fun change(): Reaction {
            delay(random.nextLong(maxPause.inWholeMicroseconds).microseconds)
            val kind =
                when (fixture.state) {
                    RTC.LifeCycleState.ACTIVE_STATE ->
                        if (aborts && random.nextBoolean()) Kind.ABORT else Kind.DEACTIVATION
                    RTC.LifeCycleState.ERROR_STATE -> Kind.RESET
                    else -> Kind.ACTIVATION
                }
            val called = System.nanoTime()
            val code =
                when (kind) {
                    Kind.ACTIVATION -> fixture.activate()
                    Kind.DEACTIVATION -> fixture.deactivate()
                    Kind.RESET -> fixture.reset()
                    Kind.ABORT -> ReturnCode_t.RTC_OK.also { fixture.fail() }
                }
            check(code == ReturnCode_t.RTC_OK) { "${fixture.instanceName}: ${kind.label} failed" }
            val noticed =
                withTimeout(5.seconds) {
                    var arrival = arrivals.receive()
                    while (arrival.first.new != kind.to) arrival = arrivals.receive()
                    arrival.second
                }
            // An abort happens at the context's next execution: timed from the fixture's record of it.
            val changed =
                if (kind == Kind.ABORT) fixture.transitions.last { it.to == RTC.LifeCycleState.ERROR_STATE }.at
                else called
            return Reaction(kind, noticed - changed)
        }
        try {
            val warmed = warmUp?.make { change() } ?: 0
            val timed = JitCompilation.during { List(count) { change() } }
            val jit =
                "warm-up $warmed changes; then the JIT compiled for ${timed.compiledMillis ?: "?"} ms of the ${figure(timed.millis / 1000.0)} s timed"
            return Changes(timed.value, jit)
        } finally {
            subscription.cancel()
        }
    }

    /** The timed [reactions], and what the [jit] did: the warm-up's length, the compiling while they were timed. */
    private class Changes(val reactions: List<Reaction>, val jit: String)

    /** The kinds of change timed, and the state each ends in. */
    private enum class Kind(val label: String, val to: LifeCycle) {
        ACTIVATION("activations", LifeCycle.ACTIVE),
        DEACTIVATION("deactivations", LifeCycle.INACTIVE),
        ABORT("aborts", LifeCycle.ERROR),
        RESET("resets", LifeCycle.INACTIVE),
    }

    /** A change of [kind], noticed [nanos] after it was made. */
    private class Reaction(val kind: Kind, val nanos: Long)

    private companion object {
        const val POLLED = 10

        /** A relay whose context runs at 20 Hz: an abort, made at the context's next execution, comes within 50 ms. */
        val pushed = ComponentType("relay", Scenarios.relay.ports, Scenarios.relay.parameters, rate = 20.0)
    }
}
