package org.rtcoord.dsl

import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.withTimeout
import org.rtcoord.ComponentNode
import org.rtcoord.RtcEvent
import kotlin.time.Duration

/**
 * What a rule's handler (or a timer) can do. Every action suspends until done and fails with an
 * [org.rtcoord.RtcException] the handler may catch; an uncaught failure is reported and the coordinator
 * keeps running.
 */
@RtcDsl
public class Reaction internal constructor(
    private val engine: Engine,
    /** The event that fired the rule; null for timers. */
    public val event: RtcEvent?,
) {
    private val source: ComponentRef
        get() = (event?.source as? ComponentNode)?.let { engine.reference(it) }
            ?: throw IllegalStateException("this reaction has no source component (it did not come from a component event)")

    /** A component, by name, path or pattern. */
    public fun component(name: String): ComponentRef = engine.componentRef(name)

    /** A port, as `component:port`. */
    public fun port(path: String): PortRef = engine.portRef(path)

    /** A manager. */
    public fun manager(name: String = "manager.mgr"): ManagerRef = ManagerRef(name, engine)

    /** Activates the component that fired the rule. */
    public suspend fun activate(): Unit = source.activate()

    /** Deactivates the component that fired the rule. */
    public suspend fun deactivate(): Unit = source.deactivate()

    /** Resets the component that fired the rule. */
    public suspend fun reset(): Unit = source.reset()

    /** Makes the component that fired the rule exit. */
    public suspend fun exit(): Unit = source.exit()

    /** Disconnects every port of the component that fired the rule. */
    public suspend fun disconnectAll(): Unit = source.disconnectAll()

    /** Connects out-port [from] to in-port [to] (refs or `component:port` text), with connector [properties]. */
    public suspend fun connect(from: Any, to: Any, properties: Map<String, String> = emptyMap()) {
        val (out, into) = engine.portOf(from) to engine.portOf(to)
        val target = into.port()
        engine.act("connect ${out.port().path} to ${target.path}", out.component, namesItself = true) { it.port(out.name).connect(listOf(target), properties) }
    }

    /** Removes every connection between [a] and [b]. */
    public suspend fun disconnect(a: Any, b: Any) {
        val (first, second) = engine.portOf(a) to engine.portOf(b)
        engine.act("disconnect ${first.port().path} from ${second.port().path}", first.component, namesItself = true) { node ->
            val port = node.port(first.name)
            val peer = second.port().path
            port.connections().filter { connection -> connection.ports.any { it.path == peer } }.forEach { port.disconnect(it.id) }
        }
    }

    /** Runs [block], failing with [TimedOut] if it takes longer than [timeout]. */
    public suspend fun <T> within(timeout: Duration, block: suspend () -> T): T = try {
        withTimeout(timeout) { block() }
    } catch (e: TimeoutCancellationException) {
        throw TimedOut("did not finish within $timeout")
    }

    /** Writes [message] to the coordinator's log. */
    public fun log(message: String): Unit = engine.log(message)
}

/** A [Reaction.within] block that ran out of time. */
public class TimedOut(message: String) : Exception(message)
