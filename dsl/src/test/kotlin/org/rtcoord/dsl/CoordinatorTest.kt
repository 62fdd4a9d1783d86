package org.rtcoord.dsl

import java.util.Collections
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.AmbiguousNameException
import org.rtcoord.ClosedException
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.RtcTree
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Scenarios

/** The engine behind the DSL, driven by coordinations written directly in Kotlin. */
class CoordinatorTest : CoordinatedSystem() {
    @Test
    fun `a failing handler is reported and the coordinator keeps reacting`(): Unit = runBlocking {
        var calls = 0
        coordinator {
            on(component("gyro0")).state(ERROR) {
                calls++
                reset()
                if (calls == 1) error("first reaction fails after the reset")
                activate()
            }
        }
            .use { coordinator ->
                coordinator.start()
                system.component("gyro0").fail()
                await("the failure to be counted") { coordinator.failures == 1 }
                assertTrue(
                    log.any { it.contains("failed: IllegalStateException: first reaction fails after the reset") },
                    log.toString(),
                )
                system.component("gyro0").activate()
                system.component("gyro0").fail()
                await("the second reaction to reactivate gyro0") {
                    calls == 2 && system.component("gyro0").state == RTC.LifeCycleState.ACTIVE_STATE
                }
            }
    }

    @Test
    fun `a closed coordinator says so when started again`(): Unit = runBlocking {
        val coordination =
            Coordination(emptyList(), config, name = "gyro watch").apply {
                on(component("gyro0")).state(ERROR) { reset() }
            }
        val coordinator = Coordinator(tree, coordination)
        coordinator.start()
        coordinator.close()
        // Before, kotlinx's JobCancellationException; then "coordinator: closed", not saying which.
        val closed = assertThrows(ClosedException::class.java) { runBlocking { coordinator.start() } }
        assertEquals("coordinator gyro watch: closed", closed.message)
    }

    @Test
    fun `configure makes the component use what it sets and keeps the active set active`(): Unit = runBlocking {
        val configured = AtomicInteger()
        coordinator {
            on(component("laser0")).state(ERROR) {
                component("laser_localise0").configure { set("gain", "2.0") }
                component("laser_localise0").configure {
                    inSet("precise")
                    set("gain", "0.25")
                }
                configured.incrementAndGet()
            }
        }
            .use { coordinator ->
                coordinator.start()
                system.component("laser0").fail()
                val localiser = system.component("laser_localise0")
                await("laser_localise0 to use gain 2.0") { localiser.parameter("gain") == "2.0" }
                await("both changes to be made") { configured.get() == 1 }
                assertEquals("default", localiser.activeConfigurationSet)
                assertEquals(
                    "0.25",
                    tree
                        .componentNamed("laser_localise0")
                        .also { it.refresh() }
                        .configuration()
                        .sets
                        .getValue("precise")["gain"],
                )
                assertEquals(0, coordinator.failures, log.toString())
            }
    }

    @Test
    fun `fsmState rules fire as the FSM enters each state, nested ones after the state holding them`(): Unit =
        runBlocking {
            val microwave = system.runtime.create(Scenarios.microwave, "Microwave0")
            val fired = CopyOnWriteArrayList<Pair<Long, String>>()
            coordinator {
                on(component("Microwave0")).fsmState("Operational") {
                    fired += it.sequence to "Operational after ${it.old}"
                }
                on(component("Microwave0")).fsmState("Idle") { fired += it.sequence to "Idle after ${it.old}" }
            }
                .use { coordinator ->
                    coordinator.start()
                    microwave.fsmEvent("open")
                    microwave.fsmEvent("close")
                    await("both rules") { fired.size == 2 }
                    // Published in that order; each rule's handler runs in a coroutine of its own, so they may start in
                    // either.
                    assertEquals(
                        listOf("Operational after Disabled", "Idle after Operational"),
                        fired.sortedBy { it.first }.map { it.second },
                    )
                }
        }

    @Test
    fun `guards narrow a rule`(): Unit = runBlocking {
        val fired = CopyOnWriteArrayList<String>()
        val guarded = AtomicInteger()
        coordinator {
            on(component("laser0"))
                .where {
                    (component("laser_localise0").state() == org.rtcoord.LifeCycle.INACTIVE).also {
                        guarded.incrementAndGet()
                    }
                }
                .state(ERROR) { fired += "guarded" }
            on(component("laser0")).state(ERROR) { fired += "plain" }
        }
            .use { coordinator ->
                coordinator.start()
                system.component("laser0").fail()
                // A guard reads the system when its rule's turn comes: wait for it before changing what it reads.
                await("the plain rule, and the guard to have read the first time") {
                    "plain" in fired && guarded.get() == 1
                }
                tree
                    .component("/${naming.address}/${org.rtcoord.runtime.RuntimeProcess.hostContext}/laser0.rtc")
                    .reset()
                tree.componentNamed("laser_localise0").deactivate()
                tree.componentNamed("laser0").activate()
                system.component("laser0").fail()
                await("both rules") { "guarded" in fired && fired.count { it == "plain" } == 2 }
                assertEquals(1, fired.count { it == "guarded" }, "the guard held only the second time")
            }
    }

    @Test
    fun `a component already in ERROR at the start fires the level-triggered rule once, not the edge-triggered one`():
        Unit = runBlocking {
        val fired = CopyOnWriteArrayList<String>()
        system.component("gyro0").fail()
        await("gyro0 to be in ERROR before the coordinator starts") {
            system.component("gyro0").state == RTC.LifeCycleState.ERROR_STATE
        }
        coordinator {
            on(component("gyro0")).state(ERROR, includeCurrent = true) { event ->
                fired += "level ${event.old}->${event.new}"
            }
            on(component("gyro0")).state(ERROR) { fired += "edge" }
        }
            .use { coordinator ->
                coordinator.start()
                await("the level-triggered rule") { fired.isNotEmpty() }
                tree.componentNamed("gyro0").reset()
                tree.componentNamed("gyro0").activate()
                system.component("gyro0").fail()
                await("both rules on the next failure") { fired.size == 3 }
                assertEquals(
                    listOf("edge", "level ACTIVE->ERROR", "level ERROR->ERROR"),
                    fired.sorted(),
                    "the edge-triggered rule saw only the transition",
                )
            }
    }

    @Test
    fun `components names every match of a pattern for a handler to act on, and warn logs a warning`(): Unit =
        runBlocking {
            val found = CopyOnWriteArrayList<String>()
            coordinator {
                after(0.seconds) {
                    components("laser*").forEach { found += it.path().name }
                    components("nothing*").let { if (it.isEmpty()) warn("no component matches nothing*") }
                    components("laser_localise0").single().deactivate()
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    await("the timer to run") { log.any { it == "warning: no component matches nothing*" } }
                    assertEquals(listOf("laser0.rtc", "laser_localise0.rtc"), found.sorted())
                    await("laser_localise0 to be deactivated") {
                        system.component("laser_localise0").state == RTC.LifeCycleState.INACTIVE_STATE
                    }
                    assertEquals(0, coordinator.failures, log.toString())
                }
        }

    @Test
    fun `configParam follows the value in use, configParamInAnySet every set's changes with the set's id`(): Unit =
        runBlocking {
            val inUse = CopyOnWriteArrayList<String>()
            val anySet = CopyOnWriteArrayList<String>()
            coordinator {
                on(component("laser_localise0")).configParam("gain") { old, new -> inUse += "$old->$new" }
                on(component("laser_localise0")).configParamInAnySet("gain") { set, old, new ->
                    anySet += "$set:$old->$new"
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    val localiser = tree.componentNamed("laser_localise0")
                    localiser.setParameter("gain", "0.25", "precise")
                    await("the change in the inactive set") { "precise:0.5->0.25" in anySet }
                    localiser.setParameter("gain", "3.0")
                    await("the change in the active set, seen by both") {
                        inUse.any { it.endsWith("->3.0") } &&
                            anySet.any { it.startsWith("default:") && it.endsWith("->3.0") }
                    }
                    assertEquals(1, inUse.size, "a set not in use changes nothing the component uses: $inUse")
                }
        }

    @Test
    fun `a name found twice is an error listing both, and a pattern watches every match`(): Unit = runBlocking {
        system.runtime.create(Scenarios.relay, "twin0", contexts = listOf("left.host_cxt"))
        system.runtime.create(Scenarios.relay, "twin0x", contexts = listOf("right.host_cxt"))
        org.rtcoord.runtime.RuntimeProcess.start(naming.corbaloc, listOf("right.host_cxt")).use { other ->
            other.create(Scenarios.relay, "twin0")
            val ambiguous = coordinator { on(component("twin0")).state(ERROR) {} }
            val failure = assertThrows(AmbiguousNameException::class.java) { runBlocking { ambiguous.start() } }
            assertEquals(
                setOf("/${naming.address}/left.host_cxt/twin0.rtc", "/${naming.address}/right.host_cxt/twin0.rtc"),
                failure.candidates.toSet(),
            )

            val seen = Collections.synchronizedSet(mutableSetOf<String>())
            coordinator { on(component("twin*")).stateChanged { event -> seen += event.source.name } }
                .use { coordinator ->
                    coordinator.start()
                    listOf(system.component("twin0x"), other.component("twin0")).forEach { it.activate() }
                    await("both matches to report") { seen == setOf("twin0x.rtc", "twin0.rtc") }
                }
        }
    }

    @Test
    fun `a rule on a type covers the components of that type alone, those created after the start included`(): Unit =
        runBlocking {
            val failed = CopyOnWriteArrayList<String>()
            coordinator { on(component(type = "relay")).state(ERROR) { event -> failed += event.source.name } }
                .use { coordinator ->
                    coordinator.start()
                    val relay = system.runtime.create(Scenarios.relay, "watched0")
                    val laser = system.runtime.create(Scenarios.laser, "other0")
                    await("the rule to cover watched0") {
                        log.any { it.endsWith("now covers ${path("watched0.rtc")}") }
                    }
                    listOf(laser, relay).forEach {
                        it.activate()
                        it.fail()
                    }
                    await("the rule to fire for the relay") { failed == listOf("watched0.rtc") }
                    assertTrue(
                        log.none { it.endsWith("now covers ${path("other0.rtc")}") },
                        "a laser is no relay: $log",
                    )
                    assertEquals(0, coordinator.failures, log.toString())
                }
        }

    @Test
    fun `a glob rule covers components created after the start, and with includeCurrent one created already in ERROR`():
        Unit = runBlocking {
        val edge = CopyOnWriteArrayList<String>()
        val level = CopyOnWriteArrayList<String>()
        coordinator {
            on(component("*")).state(ERROR) { event -> edge += event.source.name }
            on(component("*")).state(ERROR, includeCurrent = true) { event ->
                level += "${event.source.name} ${event.old}->${event.new}"
            }
        }
            .use { coordinator ->
                coordinator.start()
                val late = system.runtime.create(Scenarios.relay, "late0")
                // Covered: both rules read late0 before its changes, so the level-triggered one sees it enter ERROR.
                await("the rules to cover late0") { log.any { it.endsWith("now covers ${path("late0.rtc")}") } }
                late.activate()
                late.fail()
                await("both rules to fire for late0") {
                    edge == listOf("late0.rtc") && level == listOf("late0.rtc ACTIVE->ERROR")
                }

                // Registered only once in ERROR, and by a runtime no manager lists: found in ERROR, whenever the tree
                // looks.
                org.rtcoord.runtime.RuntimeProcess.start(naming.corbaloc).use { unmanaged ->
                    val broken = unmanaged.create(Scenarios.relay, "late1", bind = false)
                    broken.activate()
                    broken.fail()
                    await("late1 to be in ERROR before it is registered") {
                        broken.state == RTC.LifeCycleState.ERROR_STATE
                    }
                    unmanaged.bind("late1.rtc", broken.ref)
                    await("the level-triggered rule to fire for late1, in ERROR when it was found") {
                        "late1.rtc ERROR->ERROR" in level
                    }
                    assertEquals(
                        listOf("late0.rtc"),
                        edge.toList(),
                        "the edge-triggered rule saw no transition of late1",
                    )
                    assertEquals(1, broken.observerIds.size, "one observer for both rules")
                }

                late.exit()
                await("the rules to stop watching late0") {
                    log.any { it.endsWith("/late0.rtc is gone: '*' no longer covers it") }
                }
                assertEquals(0, coordinator.failures, log.toString())
            }
    }

    @Test
    fun `a reference and the rules on it follow a component re-created at its path`(): Unit = runBlocking {
        val reactions = AtomicInteger()
        coordinator {
            val gyro = component("gyro0")
            on(gyro).state(ERROR) {
                gyro.reset()
                reactions.incrementAndGet()
            }
        }
            .use { coordinator ->
                coordinator.start()
                val host = "/${naming.address}/${org.rtcoord.runtime.RuntimeProcess.hostContext}"
                tree.component("$host/gyro0.rtc").exit()
                await("gyro0 to be gone") { system.runtime.components.none { it.instanceName == "gyro0" } }
                RtcTree(config).use { other -> other.manager("$host/manager.mgr").create("gyro", "gyro0") }
                val new = system.component("gyro0")

                await("the rule to watch the new gyro0") { new.observerIds.size == 1 }
                new.activate()
                new.fail()
                await("the rule to fire on the new gyro0 and reset it") {
                    reactions.get() == 1 && new.state == RTC.LifeCycleState.INACTIVE_STATE
                }
                assertEquals(1, coordinator.treeSubscriptions, "the rule's subscription moved to the new gyro0")
                assertEquals(0, coordinator.failures, log.toString())
            }
    }

    @Test
    fun `a rule on a component its handler deletes and creates again follows the new one`(): Unit = runBlocking {
        val reactions = AtomicInteger()
        coordinator {
            on(component("gyro0")).state(ERROR) { reactions.incrementAndGet() }
            after(0.seconds) {
                manager().delete("gyro0")
                manager().create("gyro", "gyro0")
            }
        }
            .use { coordinator ->
                coordinator.start()
                await("gyro0 to be created again") { log.any { it.startsWith("created ") } }
                val new = system.component("gyro0")
                await("the rule to watch the new gyro0") { new.observerIds.size == 1 }
                new.activate()
                new.fail()
                await("the rule to fire on the new gyro0") { reactions.get() == 1 }
                assertEquals(0, coordinator.failures, log.toString())
            }
    }

    @Test
    fun `a name server written another way is the same one, and manager() is not ambiguous beside it`(): Unit =
        runBlocking {
            coordinator {
                on(context("/localhost:${naming.port}")).unreachable { log("the name server stopped answering") }
                after(0.seconds) { manager().create("gyro", "gyro1") }
            }
                .use { coordinator ->
                    coordinator.start()
                    await("gyro1 to be created through the one master manager") {
                        log.any { it.startsWith("created ") }
                    }
                    assertEquals(
                        listOf(naming.address),
                        tree.nameServers.map { it.address },
                        "one node, named as first given",
                    )
                    assertEquals(0, coordinator.failures, log.toString())
                }
        }

    @Test
    fun `one plan runs twice at once, each run acting and logging on its own, and again after both ended`(): Unit =
        runBlocking {
            val coordination =
                Coordination(emptyList(), config).apply {
                    on(component("gyro0")).state(ERROR) { event ->
                        log("${event.source.name} failed; gyro0 is ${component("gyro0").state()}")
                    }
                }
            val logs = List(3) { CopyOnWriteArrayList<String>() }
            fun run(tree: RtcTree, log: MutableList<String>) =
                Coordinator(tree, coordination, EventOptions(WatchMode.PUSH)) { log += it }
            fun reactions(log: List<String>) = log.count { it == "gyro0.rtc failed; gyro0 is ERROR" }
            val gyro = system.component("gyro0")
            RtcTree(config).use { otherTree ->
                run(tree, logs[0]).use { first ->
                    run(otherTree, logs[1]).use { second ->
                        first.start()
                        second.start()
                        gyro.fail()
                        await("both runs to react") { reactions(logs[0]) == 1 && reactions(logs[1]) == 1 }
                    }
                }
            }
            tree.componentNamed("gyro0").reset()
            gyro.activate()
            run(tree, logs[2]).use { third ->
                third.start()
                gyro.fail()
                await("a third run to react") { reactions(logs[2]) == 1 }
            }
            assertEquals(listOf(1, 1, 1), logs.map(::reactions), logs.toString())
        }

    @Test
    fun `timers run, and closing the coordinator stops them and detaches its observers`(): Unit = runBlocking {
        var ticks = 0
        val coordinator = coordinator {
            every(30.milliseconds) { ticks++ }
            on(component("gyro0")).state(ERROR) {}
        }
        coordinator.start()
        await("three ticks") { ticks >= 3 }
        assertEquals(1, system.component("gyro0").observerIds.size)
        coordinator.close()
        await("the observer to be detached") { system.component("gyro0").observerIds.isEmpty() }
        await("every coroutine of the coordinator to end") { coordinator.ended }
        val after = ticks
        assertEquals(after, ticks, "no tick after close")
    }
}
