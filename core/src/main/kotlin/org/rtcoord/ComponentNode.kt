package org.rtcoord

import RTC.ExecutionContext
import RTC.ReturnCode_t
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.withContext
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.ComponentReader
import org.rtcoord.internal.ConfigurationWriter
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.name
import org.rtcoord.internal.orFail
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TimeSource

/**
 * An RT Component. Its [snapshots] hold what was last read; operations act on the live component,
 * wait for the effect where there is one to wait for (a lifecycle operation returns once the state is
 * reached), and fail with an [RtcException] naming this path and the reason.
 */
public class ComponentNode internal constructor(
    path: RtcPath,
    core: TreeCore,
    internal val component: ComponentObject,
    /** The naming context it is bound in at [path], if that is where the tree found it. */
    private val namingParent: NamingDirectory? = null,
) : Node(path, core) {
    private val subject: String get() = path.toString()

    init {
        component.knownAt(path)
    }

    override val kind: NodeKind get() = NodeKind.COMPONENT

    /** The latest snapshot, null before the first read. Never waits. */
    public val snapshots: StateFlow<ComponentSnapshot?> get() = component.snapshot

    /** The latest snapshot, read now if there is none yet. */
    public suspend fun snapshot(): ComponentSnapshot = component.loaded(subject)

    /** What a listing shows, as last read by a full read or a summary read; null before either. Never waits. */
    public val summaries: StateFlow<ComponentSummary?> get() = component.summary

    /**
     * Reads what a listing shows of the component now (see [ComponentSummary]): fewer calls than
     * [refresh]. The [snapshots] stay as they were.
     */
    public suspend fun refreshSummary(): ComponentSummary = component.refreshSummary(subject)

    override suspend fun refresh(depth: Int) {
        component.refresh(subject)
    }

    /** The configuration sets, read now if they never were (later refreshes keep them up to date). */
    public suspend fun configuration(): ConfigurationSnapshot = snapshot().configuration ?: component.loadConfiguration(subject)

    /**
     * Whether the component is a composite and whether it is part of one, read now: snapshots leave it
     * out, since it costs two calls and OpenRTM-aist composites are rare.
     */
    public suspend fun composition(): Composition =
        withContext(core.remote.dispatcher) { ComponentReader(core.remote, subject, component.ref).readComposition() }

    /** Whether this and [other] are the same component, reached by different paths or not. */
    public fun isSameComponent(other: ComponentNode): Boolean = component === other.component

    /** The component's state in [context], read now. */
    public suspend fun state(context: ContextSelector = ContextSelector.DEFAULT): LifeCycle {
        val (_, ec) = resolve(context)
        return LifeCycle.of(core.remote.call(subject, "get_component_state") { ec.get_component_state(component.ref) })
    }

    /** Activates the component in [context] and waits until it is ACTIVE. */
    @JvmSynthetic
    public suspend fun activate(context: ContextSelector = ContextSelector.DEFAULT, deadline: Duration? = null): Unit =
        transition("activate", context, LifeCycle.INACTIVE, LifeCycle.ACTIVE, deadline) { it.activate_component(component.ref) }

    /** Deactivates the component in [context] and waits until it is INACTIVE. */
    @JvmSynthetic
    public suspend fun deactivate(context: ContextSelector = ContextSelector.DEFAULT, deadline: Duration? = null): Unit =
        transition("deactivate", context, LifeCycle.ACTIVE, LifeCycle.INACTIVE, deadline) { it.deactivate_component(component.ref) }

    /** Resets the component from ERROR in [context] and waits until it is INACTIVE. */
    @JvmSynthetic
    public suspend fun reset(context: ContextSelector = ContextSelector.DEFAULT, deadline: Duration? = null): Unit =
        transition("reset", context, LifeCycle.ERROR, LifeCycle.INACTIVE, deadline) { it.reset_component(component.ref) }

    /**
     * Asks the component to exit: it finalises and leaves its contexts; returns once its manager has also
     * unbound it from the naming context the tree found it in, which OpenRTM-aist does shortly after.
     */
    public suspend fun exit() {
        core.remote.call(subject, "exit") { component.ref.exit() }.orFail(subject, "exit")
        awaitUnbound("exit")
    }

    /**
     * Waits until the component's name is no longer bound to it in its naming context (a manager unbinds
     * an exited component at its next clean-up), then lists the context again. A component the tree found
     * below a manager has no binding to wait for.
     */
    internal suspend fun awaitUnbound(operation: String) {
        val context = namingParent ?: return
        val limit = core.remote.defaultDeadline
        val deadline = TimeSource.Monotonic.markNow() + limit
        var pause = 5.milliseconds
        while (context.binds(name, component)) {
            if (deadline.hasPassedNow()) {
                throw TimedOutException(subject, "$operation (the component finalised, but is still bound in naming)", limit.inWholeMilliseconds)
            }
            delay(pause)
            pause = (pause * 2).coerceAtMost(50.milliseconds)
        }
        context.relist()
    }

    /** The port named [name] (without the instance prefix). */
    public suspend fun port(name: String): Port {
        if (snapshot().port(name) == null) refresh()
        val snapshot = snapshot()
        if (snapshot.port(name) == null) {
            throw NotFoundException("$subject:$name", "no such port (ports: ${snapshot.ports.joinToString { it.name }.ifEmpty { "none" }})")
        }
        return Port(this, name)
    }

    /** Disconnects every connection of every port. */
    public suspend fun disconnectAll() {
        snapshot().ports.forEach { port(it.name).disconnectAll() }
    }

    /** The execution context [context] of this component. */
    public suspend fun executionContext(context: ContextSelector = ContextSelector.DEFAULT): ExecutionContextView {
        val (handle, ec) = resolve(context)
        return ExecutionContextView(this, handle, ec)
    }

    /**
     * Sets [parameter] to [value] in configuration set [set] (the active one by default); see [setParameters].
     */
    public suspend fun setParameter(parameter: String, value: String, set: String? = null): Unit = setParameters(mapOf(parameter to value), set)

    /**
     * Sets several parameters of configuration set [set] (the active one by default) in one call, so
     * either all change or none does, and makes the change take effect. Checked first, before anything
     * changes: the set and every parameter must exist, and each value must meet the constraint the
     * component declares for it in its `__constraints__` set (`0<x<10`, `(slow,fast)`). OpenRTM-aist
     * leaves a component with no active set after a write, applying nothing: so the set that was active
     * (or [set], when none was) is activated again, and the values are read back with a set active.
     * A component with no active set needs [set] named.
     */
    public suspend fun setParameters(values: Map<String, String>, set: String? = null) {
        configurationWriter().setValues(values, set)
        refresh()
    }

    /** Makes configuration set [id] the active one; this works on a component that has no active set too. */
    public suspend fun activateConfigurationSet(id: String) {
        configurationWriter().activate(id)
        refresh()
    }

    /** Adds configuration set [id] holding [values]; the active set stays active. */
    public suspend fun addConfigurationSet(id: String, values: Map<String, String>) {
        configurationWriter().add(id, values)
        refresh()
    }

    /** Removes configuration set [id] (one added at run time, not the active one); the active set stays active. */
    public suspend fun removeConfigurationSet(id: String) {
        configurationWriter().remove(id)
        refresh()
    }

    private fun configurationWriter() = ConfigurationWriter(core.remote, core.orb.orb, subject, component.ref)

    internal suspend fun resolve(selector: ContextSelector): Pair<Int, ExecutionContext> {
        val snapshot = snapshot()
        val handle = when (selector) {
            is ContextSelector.Handle -> selector.handle
            is ContextSelector.Index -> {
                val ordered = snapshot.contexts.filter { it.owned } + snapshot.contexts.filter { !it.owned }
                ordered.getOrNull(selector.index)?.handle
                    ?: throw NotFoundException(subject, "no execution context at index ${selector.index} (it has ${ordered.size})")
            }
        }
        val context = component.contexts[handle]
            ?: throw NotFoundException(subject, "no execution context with handle $handle (handles: ${component.contexts.keys.sorted().joinToString()})")
        return handle to context
    }

    private suspend fun transition(
        operation: String,
        selector: ContextSelector,
        from: LifeCycle,
        to: LifeCycle,
        deadline: Duration?,
        call: (ExecutionContext) -> ReturnCode_t,
    ) {
        val (handle, ec) = resolve(selector)
        val code = core.remote.call(subject, operation, deadline) { call(ec) }
        if (code == ReturnCode_t.PRECONDITION_NOT_MET) {
            val now = runCatching { state(ContextSelector.Handle(handle)) }.getOrDefault(LifeCycle.UNKNOWN)
            code.orFail(subject, operation, "the component is $now in context $handle, not $from")
        }
        code.orFail(subject, operation, "in context $handle")
        val reached = awaitState(operation, ec, handle, to, deadline ?: core.remote.defaultDeadline)
        component.snapshot.value?.let { snapshot ->
            component.publish(snapshot.copy(contexts = snapshot.contexts.map { if (it.handle == handle) it.copy(state = reached) else it }))
        }
    }

    /** Polls the state until it is [target], fails at once if the component fell into ERROR instead. */
    private suspend fun awaitState(operation: String, ec: ExecutionContext, handle: Int, target: LifeCycle, limit: Duration): LifeCycle {
        val deadline = TimeSource.Monotonic.markNow() + limit
        var pause = 1.milliseconds
        while (true) {
            val state = LifeCycle.of(core.remote.call(subject, "get_component_state") { ec.get_component_state(component.ref) })
            if (state == target) return state
            if (state == LifeCycle.ERROR) throw OperationFailedException(subject, operation, ReturnCode_t.RTC_ERROR.name(), "the component went to ERROR in context $handle")
            if (deadline.hasPassedNow()) throw TimedOutException(subject, "$operation (waiting for $target, still $state)", limit.inWholeMilliseconds)
            delay(pause)
            pause = (pause * 2).coerceAtMost(20.milliseconds)
        }
    }
}
