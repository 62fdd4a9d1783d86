package org.rtcoord

import RTC.ExecutionContext
import RTC.ReturnCode_t
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.ConcurrentLinkedQueue
import kotlin.random.Random
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.internal.toLifeCycle
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.StateTransition
import org.rtcoord.runtime.naming.NamingService

/**
 * Components change state (activate, deactivate, fail, reset) and connections at random, with a fixed seed, while a
 * tree watches them all in push mode; the fixtures log what really happened. Every transition must arrive as exactly
 * one event, in order: none lost, none phantom, and no component reported lost. The default build runs a smoke of it
 * (50 components for 5 s); the soak itself, 200 components for a minute or more, runs on request: `scripts/soak
 * --minutes N` (`-Drtcoord.soak.minutes=N`).
 */
class SoakTest {
    /** A relay executing at 10 Hz, so an injected failure turns into ERROR within a tenth of a second. */
    private val type = ComponentType("soak", Scenarios.relay.ports, Scenarios.relay.parameters, rate = 10.0)

    private class Seen(val transition: Pair<LifeCycle, LifeCycle>, val at: Long)

    @Test
    fun `components changing at random lose no transition and invent none`(): Unit = runBlocking {
        val soakMinutes = System.getProperty("rtcoord.soak.minutes")?.toDoubleOrNull()
        val length = soakMinutes?.minutes ?: SMOKE_LENGTH
        val size = if (soakMinutes != null) COMPONENTS else SMOKE_COMPONENTS
        NamingService.start().use { naming ->
            Scenarios.scale(naming.corbaloc, size, type).use { system ->
                RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                    val seen = ConcurrentHashMap<String, ConcurrentLinkedQueue<Seen>>()
                    val alarms = ConcurrentLinkedQueue<RtcEvent>()
                    val attaching = TimeSource.Monotonic.markNow()
                    tree.on(
                        "/${naming.address}/${RuntimeProcess.hostContext}",
                        RtcEvent::class.java,
                        EventOptions(WatchMode.PUSH),
                    ) { event ->
                        when (event) {
                            is StateChanged ->
                                seen.getOrPut(event.source.name.removeSuffix(".rtc")) { ConcurrentLinkedQueue() } +=
                                    Seen(event.old to event.new, System.nanoTime())
                            is HeartbeatLost,
                            is BecameZombie,
                            is Recovered,
                            is ComponentFinalized -> alarms += event
                            else -> Unit
                        }
                    }
                    await("an observer on every component") { system.components.all { it.observerIds.size == 1 } }
                    println("soak: $size components watched in ${attaching.elapsedNow()}")

                    val begun = System.nanoTime()
                    val driven = Churn(system.components, system::connect, Random(SEED)).run(length)
                    delay(SETTLING) // failures injected last take effect at the next execution
                    val truth =
                        system.components.associate { it.instanceName to it.transitions.map { t -> t.pair() to t } }
                    // Lost events never come: the comparison below reports them.
                    runCatching {
                        await("the events of every transition", 30.seconds) {
                            truth.all { (name, transitions) -> (seen[name]?.size ?: 0) >= transitions.size }
                        }
                    }
                    delay(SETTLING) // time for a phantom to show up after the last real event

                    var lost = 0
                    var phantom = 0
                    var maxLatency = 0L
                    for ((name, transitions) in truth) {
                        val events = seen[name]?.toList().orEmpty()
                        val matched = alignment(transitions.map { it.first }, events.map { it.transition })
                        lost += transitions.size - matched.size
                        phantom += events.size - matched.size
                        if (matched.size != transitions.size || matched.size != events.size) {
                            fun Pair<LifeCycle, LifeCycle>.text(at: Long) = "$first>$second@${(at - begun) / 1_000_000}"
                            println("soak: $name happened ${transitions.map { (pair, t) -> pair.text(t.at) }}")
                            println("soak: $name reported ${events.map { it.transition.text(it.at) }}")
                        }
                        matched.forEach { (t, e) ->
                            maxLatency = maxOf(maxLatency, events[e].at - transitions[t].second.at)
                        }
                    }
                    val total = truth.values.sumOf { it.size }
                    println(
                        "soak: ${length.inWholeSeconds} s, $size components, ${driven.operations} operations " +
                            "(${driven.connections} connects, ${driven.disconnections} disconnects): $total transitions, " +
                            "${seen.values.sumOf { it.size }} events, $lost lost, $phantom phantom, ${alarms.size} liveness alarms, " +
                            "max latency ${maxLatency / 1_000_000} ms"
                    )
                    val observers =
                        system.components
                            .filter { it.observerIds.size != 1 }
                            .associate { it.instanceName to it.observerIds }
                    assertEquals(0, lost, "lost transitions")
                    assertEquals(0, phantom, "phantom transitions")
                    assertEquals(emptyList<RtcEvent>(), alarms.toList(), "no component died")
                    assertEquals(emptyMap<String, Set<String>>(), observers, "components with other than one observer")
                }
            }
        }
    }

    /** Drives the components: one random operation every few milliseconds, as a tool would, over CORBA. */
    private class Churn(
        private val components: List<RuntimeComponent>,
        private val connect: (String, String) -> String,
        private val random: Random,
    ) {
        var operations = 0
        var connections = 0
        var disconnections = 0
        private val contexts = HashMap<RuntimeComponent, ExecutionContext>()
        /** Each connection made and not removed yet: its out-port's component, its id, its in-port's component. */
        private val connected = ArrayList<Triple<RuntimeComponent, String, RuntimeComponent>>()

        suspend fun run(length: kotlin.time.Duration): Churn {
            val end = TimeSource.Monotonic.markNow() + length
            while (end.hasNotPassedNow()) {
                if (random.nextInt(10) < 8) changeState(components[random.nextInt(components.size)])
                else changeConnection()
                operations++
                delay(PAUSE)
            }
            return this
        }

        private fun changeState(component: RuntimeComponent) {
            val context = contexts.getOrPut(component) { component.ref.get_owned_contexts()[0] }
            val code =
                when (component.state) {
                    RTC.LifeCycleState.INACTIVE_STATE -> context.activate_component(component.ref)
                    RTC.LifeCycleState.ERROR_STATE -> context.reset_component(component.ref)
                    else ->
                        if (random.nextBoolean()) context.deactivate_component(component.ref)
                        else ReturnCode_t.RTC_OK.also { component.fail() }
                }
            // An injected failure may win the race with the operation chosen: that is fine, it is logged too.
            check(code == ReturnCode_t.RTC_OK || code == ReturnCode_t.PRECONDITION_NOT_MET) {
                "${component.instanceName}: ${code.value()}"
            }
        }

        private fun changeConnection() {
            if (connected.size < MAX_CONNECTIONS && (connected.isEmpty() || random.nextBoolean())) {
                val (from, to) = List(2) { components[random.nextInt(components.size)] }
                // OpenRTM-aist refuses a second connection between two ports, as the fixtures do.
                if (connected.any { (source, _, target) -> source === from && target === to }) return
                connected += Triple(from, connect("${from.instanceName}:out", "${to.instanceName}:in"), to)
                connections++
            } else {
                val (from, id, _) = connected.removeAt(random.nextInt(connected.size))
                val port = from.ref.get_ports().first { it.get_port_profile().name == "${from.instanceName}.out" }
                port.disconnect(id)
                disconnections++
            }
        }
    }

    private companion object {
        const val COMPONENTS = 200
        const val SMOKE_COMPONENTS = 50
        val SMOKE_LENGTH = 5.seconds
        const val SEED = 20_240_610L
        const val MAX_CONNECTIONS = 100
        val PAUSE = 10.milliseconds
        val SETTLING = 500.milliseconds

        fun StateTransition.pair(): Pair<LifeCycle, LifeCycle> = from.toLifeCycle() to to.toLifeCycle()

        /**
         * The longest common subsequence of [truth] and [events], as index pairs: what was seen of what happened. The
         * rest of [truth] was lost; the rest of [events] never happened.
         */
        fun <T> alignment(truth: List<T>, events: List<T>): List<Pair<Int, Int>> {
            val lengths = Array(truth.size + 1) { IntArray(events.size + 1) }
            for (i in truth.indices.reversed()) {
                for (j in events.indices.reversed()) {
                    lengths[i][j] =
                        if (truth[i] == events[j]) lengths[i + 1][j + 1] + 1
                        else maxOf(lengths[i + 1][j], lengths[i][j + 1])
                }
            }
            val pairs = mutableListOf<Pair<Int, Int>>()
            var i = 0
            var j = 0
            while (i < truth.size && j < events.size) {
                when {
                    truth[i] == events[j] -> {
                        pairs += i to j
                        i++
                        j++
                    }
                    lengths[i + 1][j] >= lengths[i][j + 1] -> i++
                    else -> j++
                }
            }
            return pairs
        }
    }
}
