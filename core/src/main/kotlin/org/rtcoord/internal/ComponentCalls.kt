package org.rtcoord.internal

import RTC.ExecutionContext
import RTC.RTObject
import RTC.ReturnCode_t
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TimeMark
import kotlinx.coroutines.withContext
import org.rtcoord.Composition
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle
import org.rtcoord.NotFoundException
import org.rtcoord.OperationFailedException
import org.rtcoord.TimedOutException
import org.rtcoord.TransitionOutcome
import org.rtcoord.TransitionOutcomeImpl

/** A lifecycle operation, with the state it starts from, the one it leads to, and its call on a context. */
internal enum class LifecycleOperation(
    val verb: String,
    val from: LifeCycle,
    val to: LifeCycle,
    val call: (ExecutionContext, RTObject) -> ReturnCode_t,
) {
    ACTIVATE("activate", LifeCycle.INACTIVE, LifeCycle.ACTIVE, { ec, component -> ec.activate_component(component) }),
    DEACTIVATE(
        "deactivate",
        LifeCycle.ACTIVE,
        LifeCycle.INACTIVE,
        { ec, component -> ec.deactivate_component(component) },
    ),
    RESET("reset", LifeCycle.ERROR, LifeCycle.INACTIVE, { ec, component -> ec.reset_component(component) }),
}

/**
 * The remote calls a [org.rtcoord.ComponentNode] makes besides reading ([ComponentReader]) and configuring
 * ([ConfigurationWriter]): choosing an execution context, lifecycle operations that wait for their effect, and exit.
 * Each call has the tree's deadline and every return code is checked.
 */
internal class ComponentCalls(
    private val core: TreeCore,
    private val subject: String,
    private val component: ComponentObject,
) {
    /** The component's handle for the context [selector] names, and the context. */
    suspend fun context(selector: ContextSelector): Pair<Int, ExecutionContext> {
        val snapshot = component.loaded(subject)
        val handle =
            when (selector) {
                is ContextSelector.Handle -> selector.handle
                is ContextSelector.Index -> {
                    val ordered = snapshot.contexts.filter { it.owned } + snapshot.contexts.filter { !it.owned }
                    ordered.getOrNull(selector.index)?.handle
                        ?: throw NotFoundException(
                            subject,
                            "no execution context at index ${selector.index} (it has ${ordered.size})",
                        )
                }
            }
        val context =
            component.contexts[handle]
                ?: throw NotFoundException(
                    subject,
                    "no execution context with handle $handle (handles: ${component.contexts.keys.sorted().joinToString()})",
                )
        return handle to context
    }

    /** The component's state in [selector]'s context, read now. */
    suspend fun state(selector: ContextSelector): LifeCycle = state(context(selector).second)

    private suspend fun state(ec: ExecutionContext): LifeCycle =
        core.remote.call(subject, "get_component_state") { ec.get_component_state(component.ref) }.toLifeCycle()

    /** Whether the component is a composite and whether it is part of one, read now. */
    suspend fun composition(): Composition =
        withContext(core.remote.dispatcher) { ComponentReader(core.remote, subject, component.ref).readComposition() }

    /**
     * Performs [operation] in [selector]'s context, waits until the component is in the state it leads to (within
     * [deadline], else the tree's), and publishes that state. A context that answers `RTC_ERROR`, or no answer within
     * the deadline, may only have stopped waiting for a slow callback (OpenRTM-aist's `transition_timeout`,
     * `ExecutionContextBase.waitForActivated` and the like): the state is read until the deadline, and one that arrives
     * makes a slow success.
     */
    suspend fun perform(
        operation: LifecycleOperation,
        selector: ContextSelector,
        deadline: Duration?,
    ): TransitionOutcome {
        val (handle, ec) = context(selector)
        val limit = deadline ?: core.remote.defaultDeadline
        val started = core.time.markNow()
        val code =
            try {
                core.remote.call(subject, operation.verb, limit) { operation.call(ec, component.ref) }
            } catch (e: TimedOutException) {
                null
            }
        if (code == ReturnCode_t.PRECONDITION_NOT_MET) {
            val now = runCatching { state(ec) }.getOrDefault(LifeCycle.UNKNOWN)
            code.orFail(subject, operation.verb, "the component is $now in context $handle, not ${operation.from}")
        }
        val late =
            when (code) {
                ReturnCode_t.RTC_OK -> null
                ReturnCode_t.RTC_ERROR -> code.name()
                null -> "no answer"
                else -> {
                    code.orFail(subject, operation.verb, "in context $handle") // throws: any other code is a failure
                    null
                }
            }
        val stamp = awaitState(operation, ec, handle, started + limit, limit, late)
        component.publishStates(mapOf(handle to operation.to), stamp)
        return TransitionOutcomeImpl(operation.to, late, started.elapsedNow().inWholeMilliseconds)
    }

    /**
     * Polls the state until it is [operation]'s target, failing at once if the component fell into ERROR instead (a
     * reset's ERROR is the state it leaves); returns the stamp of the read that found the target (see
     * [ComponentObject.stamp]). [late] is what the context answered when it did not report the target itself: the
     * failure at [deadline] names it with the state found.
     */
    private suspend fun awaitState(
        operation: LifecycleOperation,
        ec: ExecutionContext,
        handle: Int,
        deadline: TimeMark,
        limit: Duration,
        late: String?,
    ): Long {
        val verb = operation.verb
        val target = operation.to
        var last: LifeCycle? = null
        return pollUntil(deadline, 1.milliseconds, 20.milliseconds) {
            val stamp = component.stamp()
            val state = state(ec).also { last = it }
            if (state == LifeCycle.ERROR && operation.from != LifeCycle.ERROR) {
                throw OperationFailedException(
                    subject,
                    verb,
                    late ?: ReturnCode_t.RTC_ERROR.name(),
                    "the component went to ERROR in context $handle",
                )
            }
            stamp.takeIf { state == target }
        }
            ?: throw when (late) {
                null,
                "no answer" ->
                    TimedOutException(subject, "$verb (waiting for $target, still $last)", limit.inWholeMilliseconds)
                else ->
                    OperationFailedException(
                        subject,
                        verb,
                        late,
                        "in context $handle; still $last at its ${limit.inWholeMilliseconds} ms deadline",
                    )
            }
    }

    /** Asks the component to exit. */
    suspend fun exit() {
        core.remote.call(subject, "exit") { component.ref.exit() }.orFail(subject, "exit")
    }

    /** Whether the object no longer exists, as its ORB answers. */
    suspend fun nonExistent(): Boolean = core.remote.call(subject, "_non_existent") { component.ref._non_existent() }

    /** Changes the component's configuration (see [ConfigurationWriter]). */
    fun configuration(): ConfigurationWriter = ConfigurationWriter(core.remote, core.orb.orb, subject, component.ref)

    /** The calls on the execution context with [handle], [ec]. */
    fun onContext(handle: Int, ec: ExecutionContext): ContextCalls =
        ContextCalls(core.remote, "$subject context $handle", ec)
}

/** The remote calls on one execution context: rate, running, participants. */
internal class ContextCalls(private val remote: Remote, val subject: String, private val context: ExecutionContext) {
    suspend fun rate(): Double = remote.call(subject, "get_rate") { context.get_rate() }

    suspend fun setRate(hz: Double) {
        remote.call(subject, "set_rate") { context.set_rate(hz) }.orFail(subject, "set rate to $hz")
    }

    suspend fun isRunning(): Boolean = remote.call(subject, "is_running") { context.is_running() }

    suspend fun add(participant: ComponentObject, name: String) {
        remote.call(subject, "add_component") { context.add_component(participant.ref) }.orFail(subject, "add $name")
    }

    suspend fun remove(participant: ComponentObject, name: String) {
        remote
            .call(subject, "remove_component") { context.remove_component(participant.ref) }
            .orFail(subject, "remove $name")
    }
}
