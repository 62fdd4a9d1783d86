package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * What watching weighs while nothing happens: a tree watching ten thousand components holds a monitor and a sink for
 * each, and neither keeps a coroutine waiting, which would weigh more than the rest of them. They start one when work
 * comes, and events still flow.
 */
class IdleWatchTest {
    @Test
    fun `components watched by push hold no coroutine while idle, and events flow`(): Unit = runBlocking {
        val count = 20
        NamingService.start().use { naming ->
            Scenarios.scale(naming.corbaloc, count).use { system ->
                RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                    tree.refresh()
                    val components = tree.find { it is ComponentNode }.toList()
                    assertEquals(count, components.size)
                    val changes = CopyOnWriteArrayList<StateChanged>()
                    components.forEach {
                        tree.on(it, StateChanged::class.java, EventOptions(WatchMode.PUSH)) { e -> changes += e }
                    }
                    await("every component watched by push") {
                        tree.snapshot().components.count { it.watchMethod is WatchMethod.Pushed } == count
                    }
                    val scope = tree.core.scope.coroutineContext[Job]!!
                    await("the monitors and sinks to go idle") { scope.children.count() < count }

                    system.component("relay7").activate()
                    await("the activation to be told") {
                        changes.any { it.source.name == "relay7.rtc" && it.new == LifeCycle.ACTIVE }
                    }
                    await("the monitors and sinks to go idle again") { scope.children.count() < count }
                }
            }
        }
    }
}
