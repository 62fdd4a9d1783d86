package org.rtcoord.dsl.internal

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.async
import kotlinx.coroutines.withTimeout
import org.rtcoord.NotFoundException
import org.rtcoord.UnreachableException
import org.rtcoord.dsl.Link
import org.rtcoord.dsl.Network
import org.rtcoord.dsl.portRef

/**
 * Brings the live system to a [Network]: reads what the network names, [plan]s the difference, applies the steps one by
 * one, each within the network's step deadline, and reads the result back. The configurator of the
 * Coordinator-Configurator split: a mode machine decides where the system should be, this gets it there and says
 * whether it did. It leaves what the network does not name alone; a component that does not exist satisfies `inactive`
 * and `disconnected`, and fails the rest.
 */
internal class Configurator(private val engine: Engine, private val scope: CoroutineScope) {
    /** How a reconfiguration ended. */
    sealed class Outcome {
        /** The live system matches; [steps] were needed to get there; [connectors] join each link, as read back. */
        class Done(val steps: List<Step>, val connectors: Map<Link, List<String>>) : Outcome()

        /** It could not be brought there: [reason] names the step and object, then what went wrong. */
        class Failed(val reason: String) : Outcome()
    }

    /**
     * Applies [network]: reads, plans and applies the steps. A step that fails may have failed because the system
     * changed under it (a connector another client removed, a component someone activated): the rest is planned once
     * more from a fresh read, and only a step of that plan that fails too ends the reconfiguration.
     */
    suspend fun apply(network: Network): Outcome {
        val deadline = network.stepDeadline ?: DEFAULT_STEP_DEADLINE
        val applied = mutableListOf<Step>()
        return try {
            val steps = plan(network, read(network, deadline))
            try {
                applyAll(steps, deadline, applied)
            } catch (e: StepFailed) {
                val rest = plan(network, read(network, deadline))
                engine.log(
                    "network: ${e.message}; read again: ${if (rest.isEmpty()) "nothing left to do" else "still to do: ${rest.joinToString()}"}"
                )
                applyAll(rest, deadline, applied)
            }
            val live = read(network, deadline)
            val remaining = plan(network, live)
            if (remaining.isEmpty()) Outcome.Done(applied, live.links)
            else Outcome.Failed("read back: still to do: ${remaining.joinToString()}")
        } catch (e: StepFailed) {
            Outcome.Failed(e.message)
        }
    }

    private suspend fun applyAll(steps: List<Step>, deadline: Duration, applied: MutableList<Step>) {
        for (step in steps) {
            within(step.description, deadline) { step.apply(engine) }
            applied += step
        }
    }

    private suspend fun read(network: Network, deadline: Duration): LiveNetwork =
        LiveNetwork(
            network.components.mapValues { (component, active) ->
                within("read the state of $component", deadline) {
                    unlessAbsent(allowed = !active) { engine.withComponent(component) { it.state() } }
                }
            },
            network.configurationSets.keys.associateWith { component ->
                within("read the configuration of $component", deadline) {
                    engine.withComponent(component) { node ->
                        node.refresh()
                        node.configuration().activeSet
                    }
                }
            },
            network.connections.mapValues { (link, present) ->
                within("read the connections of ${link.from}", deadline) {
                    unlessAbsent(allowed = !present) { connectors(link) }.orEmpty()
                }
            },
        )

    /** The ids of the connections joining the link's ports, recognised by path or by OpenRTM's `instance.port` name. */
    private suspend fun connectors(link: Link): List<String> {
        val (from, to) = portRef(link.from) to portRef(link.to)
        val (path, fullName) =
            engine.withComponent(to.component.selector) { node ->
                node.port(to.name).path to "${node.snapshot().instanceName}.${to.name}"
            }
        val connections = engine.withComponent(from.component.selector) { it.port(from.name).connections() }
        return connections
            .filter { connection -> connection.ports.any { it.path == path || it.fullName == fullName } }
            .map { it.id }
    }

    /**
     * [read], or null when what it reads does not exist and that is [allowed]: a missing component is neither active
     * nor connected. One that exited is missing too, while its name still reaches it (`OBJECT_NOT_EXIST`): its manager
     * unbinds the name only at its next clean-up.
     */
    private suspend fun <T> unlessAbsent(allowed: Boolean, read: suspend () -> T): T? =
        try {
            read()
        } catch (e: NotFoundException) {
            if (allowed) null else throw e
        } catch (e: UnreachableException) {
            if (allowed && e.cause is org.omg.CORBA.OBJECT_NOT_EXIST) null else throw e
        }

    /**
     * Runs [block] as its own coroutine in [scope] and waits at most [deadline] for it. A CORBA call blocked in a
     * socket read does not give way to cancellation, so an overrunning step is cancelled and left to end there, within
     * the tree's call timeout, while the reconfiguration fails at once.
     */
    private suspend fun <T> within(what: String, deadline: Duration, block: suspend () -> T): T {
        val step = scope.async(CoroutineName(what)) { block() }
        return try {
            withTimeout(deadline) { step.await() }
        } catch (e: TimeoutCancellationException) {
            step.cancel()
            throw StepFailed("$what: did not finish within $deadline")
        } catch (e: CancellationException) {
            step.cancel()
            throw e
        } catch (e: Exception) {
            throw StepFailed("$what: ${e.message ?: e}")
        }
    }

    private class StepFailed(override val message: String) : Exception(message)

    companion object {
        /** How long a step may take when the network does not say. */
        val DEFAULT_STEP_DEADLINE: Duration = 10.seconds
    }
}
