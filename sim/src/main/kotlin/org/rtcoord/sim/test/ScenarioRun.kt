package org.rtcoord.sim.test

import java.net.InetSocketAddress
import java.time.Instant
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.ComparableTimeMark
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlin.time.toKotlinDuration
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.EventOptions
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.LogRecord
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.Subscription
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.HandlerFailure
import org.rtcoord.dsl.LiveCheck
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.SimulatedSystem

/**
 * Runs one scenario: simulates the test's system afresh, starts its coordinator on it, observes both (every event of
 * the system, every line and mode of the coordinator, from before the start), plays the steps, and stops everything.
 * The scenario stops at its first failure: a step that fails, an invariant that breaks, a handler of the coordinator
 * that fails where the scenario does not expect it, or a rule that can never fire because the system lacks what it
 * names. After the last step it waits for the system to be quiet for a moment, so that what that step set going is
 * checked too. Whatever happens, it returns a result.
 */
internal class ScenarioRun(
    private val plan: ScenarioPlan,
    private val scripts: ScriptHost,
    /** Faults applied besides the scenario's own: an explored schedule. */
    private val schedule: List<Injection> = emptyList(),
    /** How long a handler may run before the coordinator is said to have stopped reacting. */
    private val stuckAfter: Duration = STUCK,
    /** How many times as fast as the robot's clock the scenario runs ([TreeConfig.speed]). */
    private val speed: Double = 1.0,
) {
    private val test = plan.test
    private val log = CopyOnWriteArrayList<String>()
    private val broken = CompletableDeferred<TestFailure>()
    private var observer: ScenarioObserver? = null

    suspend fun run(): TestResult {
        val began = TimeSource.Monotonic.markNow()
        val failures =
            try {
                simulate()
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                listOf(
                    TestFailure(
                        test.file.path.toString(),
                        "the scenario could not be run: ${e.javaClass.simpleName}: ${e.message}",
                    )
                )
            }
        return TestResult(
            test.file,
            plan.name,
            failures,
            began.elapsedNow(),
            log.toList(),
            observer?.timeline().orEmpty(),
        )
    }

    private fun broke(failure: TestFailure) {
        broken.complete(failure)
    }

    private suspend fun simulate(): List<TestFailure> {
        val system =
            try {
                SimulatedSystem.start(
                    test.profile,
                    LOOPBACK,
                    0,
                    test.idlDirectories,
                    speed,
                    idleRequestThreads = IDLE_REQUEST_THREADS,
                )
            } catch (e: IllegalArgumentException) {
                return listOf(TestFailure(test.systemAt, "cannot simulate ${test.systemShown}: ${e.message}"))
            }
        // What the system could not be simulated as saved fails the test: it would not test the robot's system.
        if (system.warnings.isNotEmpty()) {
            system.close()
            return system.warnings.map { TestFailure(test.systemAt, "${test.systemShown}: $it") }
        }
        return system.use {
            RtcTree(TreeConfig(listOf(system.address), speed = speed)).use { tree -> coordinate(system, tree) }
        }
    }

    private suspend fun coordinate(system: SimulatedSystem, tree: RtcTree): List<TestFailure> = coroutineScope {
        // The components' log records reach the tree as OpenRTM-aist's reach a Fluentd input: a scenario's `log` step.
        tree.listenForLogs("127.0.0.1:0").let { system.sendLogsTo(InetSocketAddress(it.host, it.port)) }
        val coordination =
            try {
                scripts.load(test.coordinatorShown, test.args, tree.config)
            } catch (e: ScriptFailure) {
                return@coroutineScope e.problems.map(TestFailure::of)
            }
        val clock = ScenarioClock(tree)
        val observer =
            ScenarioObserver(SystemModel(LiveReads(system, tree, null, log)), test.source, ::broke, clock).also {
                observer = it
            }
        val observing = launch { observer.run() }
        val subscriptions = observe(tree, observer)
        try {
            Coordinator(tree, coordination, null) { line ->
                    log += line
                    observer.log(line)
                }
                .use { coordinator -> play(system, tree, coordination, coordinator, observer, observing, clock) }
        } finally {
            subscriptions.forEach(Subscription::cancel)
            observer.close()
            observing.join()
        }
    }

    private suspend fun CoroutineScope.play(
        system: SimulatedSystem,
        tree: RtcTree,
        coordination: Coordination,
        coordinator: Coordinator,
        observer: ScenarioObserver,
        observing: Job,
        clock: ScenarioClock,
    ): List<TestFailure> {
        start(system, tree, coordination, coordinator)?.let {
            return it
        }
        val origin = clock.markNow()
        observer.origin = origin
        val watching = launch { watch(tree, coordination, coordinator, observer) }
        val player =
            ScenarioPlayer(
                system,
                coordinator,
                LiveReads(system, tree, coordinator, log),
                observer,
                test.source,
                origin,
                clock,
            )
        val injecting = launch {
            inject(system, observer, clock, origin, (plan.injections + schedule).sortedBy { it.time })
        }
        val playing = async { player.play(plan.steps) }
        // The scenario lasts until its steps are done and its last fault applied, or its first failure.
        val first =
            select<TestFailure?> {
                broken.onAwait { it }
                playing.onAwait { it }
            }
                ?: select<TestFailure?> {
                    broken.onAwait { it }
                    injecting.onJoin { null }
                }
        playing.cancel()
        injecting.cancel()
        if (first == null) settle(observer, clock)
        val stuck = if (first == null) stuck(coordinator, clock) else null
        watching.cancel()
        val end = if (first == null) player.endChecks(plan.steps) else emptyList()
        // What was observed up to now is checked before the verdict: an invariant may break on the last events.
        observer.close()
        withTimeoutOrNull(DRAIN) { observing.join() }
        val failure =
            first
                ?: (if (broken.isCompleted) broken.await() else null)
                ?: unexpected(coordinator.handlerFailures).firstOrNull()
                ?: stuck
        return listOfNotNull(failure) + end
    }

    /**
     * Applies [injections] (in time order) each at its time from [origin], then waits [AFTERMATH]. One that cannot be
     * applied ends the scenario: a failure at the test's line, or for a schedule's fault a skipped run.
     */
    private suspend fun inject(
        system: SimulatedSystem,
        observer: ScenarioObserver,
        clock: ScenarioClock,
        origin: ComparableTimeMark,
        injections: List<Injection>,
    ) {
        for (injection in injections) {
            clock.delay(injection.time - origin.elapsedNow())
            try {
                injection.faults(SimFaults(system, observer::fault))
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                val why = e.message ?: e.javaClass.simpleName
                broke(
                    injection.at?.let { TestFailure(it, "at ${injection.time}: $why") }
                        ?: TestFailure(
                            "schedule",
                            "at ${TimelineEntry.seconds(injection.time)}: cannot be applied: $why",
                            skipped = true,
                        )
                )
                return
            }
        }
        // What the last fault sets going takes a moment to show (a state change polled, a handler run): it is watched
        // for first.
        if (injections.isNotEmpty()) clock.delay(AFTERMATH)
    }

    /**
     * Lets what the last steps set going finish: waits until nothing has happened for [QUIET] (at most [SETTLE]), so
     * that a handler that fails just after the last expectation held still fails the scenario.
     */
    private suspend fun settle(observer: ScenarioObserver, clock: ScenarioClock) {
        clock.withTimeoutOrNull(SETTLE) {
            while (!broken.isCompleted) {
                val seen = observer.changes.value
                clock.withTimeoutOrNull(QUIET) { observer.changes.first { it != seen } } ?: break
            }
        }
    }

    /**
     * Whether the coordinator stopped reacting: a rule's handler that has not returned [stuckAfter] after it fired,
     * which holds back the rule's later events. Waits for the handlers running now to return, each at most until then.
     */
    private suspend fun stuck(coordinator: Coordinator, clock: ScenarioClock): TestFailure? {
        for (rule in coordinator.rules) {
            val status = rule.status.value
            val since = status.lastFired?.takeIf { status.running > 0 } ?: continue
            // When it fired is the host's wall clock.
            val running = clock.robotTime(java.time.Duration.between(since, Instant.now()).toKotlinDuration())
            val left = stuckAfter - running
            if (left.isPositive() && clock.withTimeoutOrNull(left) { rule.status.first { it.running == 0 } } != null)
                continue
            return TestFailure(
                test.coordinatorShown.toString(),
                "the coordinator stopped reacting: the handler of rule '${rule.description}' had not returned $stuckAfter after it fired on ${status.lastEvent}",
                listOf(
                    "a handler that does not return holds back its rule's later events; every remote call has a deadline, so it waits on something else"
                ),
            )
        }
        return null
    }

    /** Starts [coordinator]; the failures saying why it cannot start, or null once it has. */
    private suspend fun start(
        system: SimulatedSystem,
        tree: RtcTree,
        coordination: Coordination,
        coordinator: Coordinator,
    ): List<TestFailure>? {
        val failure =
            try {
                withTimeoutOrNull(START_DEADLINE) { coordinator.start() }
                    ?: return listOf(
                        TestFailure(test.coordinatorAt, "the coordinator did not start within $START_DEADLINE")
                    )
                return null
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                e
            }
        // A rule's target that the system lacks, as `check` would say it, where the coordinator writes it.
        val check = LiveCheck(tree).check(coordination, test.coordinatorShown)
        val components = "the simulated system has ${system.components.joinToString { it.instanceName }}"
        val missing =
            (check.missing - check.cannotFire.toSet()).map {
                TestFailure(
                    it.at,
                    "${it.name}: ${it.says}",
                    listOf("the coordinator of ${test.coordinatorAt} cannot start", components),
                )
            }
        return missing.ifEmpty {
            listOf(
                TestFailure(
                    test.coordinatorAt,
                    "the coordinator cannot start: ${failure.message ?: failure.javaClass.simpleName}",
                    listOf(components),
                )
            )
        }
    }

    /**
     * While the steps play: each handler failure the scenario does not expect, each rule that can never fire (what it
     * names lacks the parameter or set it is about) breaks the scenario; each mode entered is an entry.
     */
    private suspend fun watch(
        tree: RtcTree,
        coordination: Coordination,
        coordinator: Coordinator,
        observer: ScenarioObserver,
    ) = coroutineScope {
        launch {
            var seen = 0
            coordinator.failureCounts.collect { count ->
                if (count > seen) unexpected(coordinator.handlerFailures.drop(seen)).firstOrNull()?.let(::broke)
                seen = count
            }
        }
        for (machine in coordinator.machines) launch { machine.mode.collect { observer.mode(machine.name, it) } }
        launch {
            val check = LiveCheck(tree).check(coordination, test.coordinatorShown)
            check.cannotFire.firstOrNull()?.let {
                broke(
                    TestFailure(
                        it.at,
                        "${it.name}: ${it.says}",
                        listOf("a rule or mode of the coordinator of ${test.coordinatorAt} can never fire"),
                    )
                )
            }
        }
    }

    /** Those of [failures] the scenario does not expect, each as a failure at the coordinator's line. */
    private fun unexpected(failures: List<HandlerFailure>): List<TestFailure> =
        failures
            .filter { failure -> plan.expectedHandlerFailures.none { it in failure.toString() } }
            .map { failure ->
                val at = failure.at?.let { "${test.coordinatorShown.parent?.resolve(it) ?: it}" } ?: test.coordinatorAt
                TestFailure(
                    at,
                    "${failure.subject} failed: ${failure.type}: ${failure.message}",
                    listOf(
                        "a handler of the coordinator failed; if the scenario expects it, write expectHandlerFailure(\"${failure.message}\")"
                    ) + failure.scriptFrames.drop(1).map { "at $it" },
                )
            }

    /** Hands [observer] every event of the system from now on, and what the tree knows of it now. */
    private suspend fun observe(tree: RtcTree, observer: ScenarioObserver): List<Subscription> {
        val following =
            tree.follow(tree.nameServers, OBSERVED, EventOptions(), { observer.started(it) }) { observer.event(it) }
        val managers = tree.onWatching { event ->
            if (event is ManagerDied || event is ManagerReturned) observer.event(event)
        }
        return listOf(following, managers)
    }

    internal companion object {
        val START_DEADLINE = 30.seconds

        private const val LOOPBACK = "127.0.0.1"

        /**
         * How many request threads each ORB of the simulated system keeps idle. Its system is made and closed for each
         * run: starting 64 threads for each of its ORBs, then ending them, was a fifth of the CPU an exploration spent
         * (the paper's test, 100 runs 3 at a time: 38 s of CPU with 64, 31 s with 8). A run's few components rarely
         * have more calls in flight; more threads are started when they do.
         */
        private const val IDLE_REQUEST_THREADS = 8

        /** How long the system must be quiet after the last step, and how long that may be waited for. */
        val QUIET = 200.milliseconds
        val SETTLE = 1.seconds

        /** How long the scenario lasts after its last fault applied alongside its steps, at least. */
        val AFTERMATH = 1.seconds

        /** How long a handler may run before the coordinator is said to have stopped reacting. */
        val STUCK = 10.seconds

        /** How long the last entries may take to be checked once the steps are done. */
        val DRAIN = 5.seconds

        /**
         * The events a scenario's timeline shows and its invariants are checked on: all but each port's traffic and how
         * components are watched.
         */
        val OBSERVED: Set<Class<out RtcEvent>> =
            setOf(
                StateChanged::class.java,
                FsmStateChanged::class.java,
                ComponentFinalized::class.java,
                PortConnected::class.java,
                PortDisconnected::class.java,
                ParameterChanged::class.java,
                ConfigurationSetActivated::class.java,
                ContextRateChanged::class.java,
                ContextRunningChanged::class.java,
                ManagerComponentChanged::class.java,
                NodeAppeared::class.java,
                NodeVanished::class.java,
                HeartbeatLost::class.java,
                BecameZombie::class.java,
                Recovered::class.java,
                NameServerLost::class.java,
                NameServerReturned::class.java,
                LogRecord::class.java,
            )
    }
}
