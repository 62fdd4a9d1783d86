package org.rtcoord

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.flow.StateFlow
import org.rtcoord.internal.ComponentCalls
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.LifecycleOperation
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.pollUntil

/**
 * An RT Component. Its [snapshots] hold what was last read; operations act on the live component, wait for the effect
 * where there is one to wait for (a lifecycle operation returns once the state is reached), and fail with an
 * [RtcException] naming this path and the reason.
 */
public sealed class ComponentNode(
    path: RtcPath,
    core: TreeCore,
    @get:JvmSynthetic internal val component: ComponentObject,
    /** The naming context it is bound in at [path], if that is where the tree found it. */
    private val namingParent: NamingDirectory? = null,
) : Node(path, core) {
    private val subject: String
        get() = path.toString()

    /** Where its remote calls are made. */
    @get:JvmSynthetic
    internal val calls: ComponentCalls
        get() = ComponentCalls(core, subject, component)

    init {
        component.knownAs(this)
    }

    /**
     * The component's one path, which every event, log line and result uses: where it is bound in a naming context, or
     * where the tree first found it if it found it only below a manager (a manager's listing is an alias of the naming
     * path).
     */
    public val canonicalPath: RtcPath
        get() = canonical.path

    /** The node at [canonicalPath]: this one, or the same component found at its naming path. */
    public val canonical: ComponentNode
        get() = component.canonical ?: this

    override val kind: NodeKind
        get() = NodeKind.COMPONENT

    /** The latest snapshot, null before the first read. Never waits. */
    @get:JvmSynthetic
    public val snapshots: StateFlow<ComponentSnapshot?>
        get() = component.snapshot

    /** The latest snapshot, read now if there is none yet. */
    @JvmSynthetic public suspend fun snapshot(): ComponentSnapshot = component.loaded(subject)

    /** What a listing shows, as last read by a full read or a summary read; null before either. Never waits. */
    @get:JvmSynthetic
    public val summaries: StateFlow<ComponentSummary?>
        get() = component.summary

    /**
     * Reads what a listing shows of the component now (see [ComponentSummary]): fewer calls than [refresh]. The
     * [snapshots] stay as they were.
     */
    @JvmSynthetic public suspend fun refreshSummary(): ComponentSummary = component.refreshSummary(subject)

    @JvmSynthetic
    override suspend fun refresh(depth: Int) {
        component.refresh(subject)
    }

    /** The configuration sets, read now if they never were (later refreshes keep them up to date). */
    @JvmSynthetic
    public suspend fun configuration(): ConfigurationSnapshot =
        snapshot().configuration ?: component.loadConfiguration(subject)

    /**
     * Whether the component is a composite and whether it is part of one, read now: snapshots leave it out, since it
     * costs two calls and OpenRTM-aist composites are rare.
     */
    @JvmSynthetic public suspend fun composition(): Composition = calls.composition()

    /** Whether this and [other] are the same component, reached by different paths or not. */
    public fun isSameComponent(other: ComponentNode): Boolean = component === other.component

    /** The component's state in [context], read now. */
    @JvmSynthetic
    public suspend fun state(context: ContextSelector = ContextSelector.Handle(0)): LifeCycle = calls.state(context)

    /**
     * Activates the component in [context] and waits until it is ACTIVE, within [deadline] (the tree's call timeout by
     * default). A context that answers `RTC_ERROR` because its transition timeout passed first is not a failure while
     * the state arrives before [deadline]: the outcome says it was slow.
     */
    @JvmSynthetic
    public suspend fun activate(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: Duration? = null,
    ): TransitionOutcome = calls.perform(LifecycleOperation.ACTIVATE, context, deadline)

    /** Deactivates the component in [context] and waits until it is INACTIVE; slow transitions as in [activate]. */
    @JvmSynthetic
    public suspend fun deactivate(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: Duration? = null,
    ): TransitionOutcome = calls.perform(LifecycleOperation.DEACTIVATE, context, deadline)

    /**
     * Resets the component from ERROR in [context] and waits until it is INACTIVE; slow transitions as in [activate]. A
     * reset whose `on_reset` fails looks like a slow one until [deadline], since the component stays in ERROR either
     * way: it fails then, naming the state.
     */
    @JvmSynthetic
    public suspend fun reset(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: Duration? = null,
    ): TransitionOutcome = calls.perform(LifecycleOperation.RESET, context, deadline)

    /**
     * Asks the component to exit: it finalises and leaves its contexts; returns once its manager has also unbound it
     * from the naming context the tree found it in, which OpenRTM-aist does shortly after.
     */
    @JvmSynthetic
    public suspend fun exit() {
        calls.exit()
        awaitUnbound("exit")
    }

    /**
     * Waits until the component's name is no longer bound to it in its naming context (a manager unbinds an exited
     * component at its next clean-up), then lists the context again. A component the tree found below a manager has no
     * binding to wait for.
     */
    @JvmSynthetic
    internal suspend fun awaitUnbound(operation: String) {
        val context = namingParent ?: return
        val limit = core.remote.defaultDeadline
        pollUntil(core.time.markNow() + limit, 5.milliseconds, 50.milliseconds) {
            Unit.takeUnless { context.binds(name, component) }
        }
            ?: throw TimedOutException(
                subject,
                "$operation (the component finalised, but is still bound in naming)",
                limit.inWholeMilliseconds,
            )
        context.relist()
    }

    /** The port named [name] (without the instance prefix). */
    @JvmSynthetic
    public suspend fun port(name: String): Port {
        if (snapshot().port(name) == null) refresh()
        val snapshot = snapshot()
        if (snapshot.port(name) == null) {
            throw NotFoundException(
                "$subject:$name",
                "no such port (ports: ${snapshot.ports.joinToString { it.name }.ifEmpty { "none" }})",
            )
        }
        return PortImpl(this, name)
    }

    /** Disconnects every connection of every port. */
    @JvmSynthetic
    public suspend fun disconnectAll() {
        snapshot().ports.forEach { port(it.name).disconnectAll() }
    }

    /** The execution context [context] of this component. */
    @JvmSynthetic
    public suspend fun executionContext(context: ContextSelector = ContextSelector.Handle(0)): ExecutionContextView {
        val (handle, ec) = calls.context(context)
        return ExecutionContextViewImpl(this, handle, calls.onContext(handle, ec))
    }

    /**
     * Sets [parameter] to [value] in configuration set [set] (the active one by default), refusing a value outside its
     * constraint only when [strict]; see [setParameters].
     */
    @JvmSynthetic
    public suspend fun setParameter(
        parameter: String,
        value: String,
        set: String? = null,
        strict: Boolean = false,
    ): List<String> = setParameters(mapOf(parameter to value), set, strict)

    /**
     * Sets several parameters of configuration set [set] (the active one by default) in one call, so either all change
     * or none does, and makes the change take effect. Checked first, before anything changes: the set and every
     * parameter must exist. A value outside the constraint the component declares for it in its `__constraints__` set
     * (`0<x<10`, `(slow,fast)`) is written, as OpenRTM-aist writes it (it never checks them), and returned as a
     * warning; with [strict] it is refused ([BadParameterException]) and nothing changes. A value the set holds already
     * is never refused. OpenRTM-aist leaves a component with no active set after a write, applying nothing: so the set
     * that was active (or [set], when none was) is activated again, and the values are read back with a set active. A
     * component with no active set needs [set] named.
     *
     * @return one line per value written outside its constraint (`gain: '42' is outside 0<x<10`), empty when none was.
     */
    @JvmSynthetic
    public suspend fun setParameters(
        values: Map<String, String>,
        set: String? = null,
        strict: Boolean = false,
    ): List<String> {
        val warnings = calls.configuration().setValues(values, set, strict)
        refresh()
        return warnings
    }

    /** Makes configuration set [id] the active one; this works on a component that has no active set too. */
    @JvmSynthetic
    public suspend fun activateConfigurationSet(id: String) {
        calls.configuration().activate(id)
        refresh()
    }

    /** Adds configuration set [id] holding [values]; the active set stays active. */
    @JvmSynthetic
    public suspend fun addConfigurationSet(id: String, values: Map<String, String>) {
        calls.configuration().add(id, values)
        refresh()
    }

    /** Removes configuration set [id] (one added at run time, not the active one); the active set stays active. */
    @JvmSynthetic
    public suspend fun removeConfigurationSet(id: String) {
        calls.configuration().remove(id)
        refresh()
    }
}

/** The [ComponentNode]s the tree makes ([Node] says why that class is sealed). */
internal class ComponentNodeImpl(
    path: RtcPath,
    core: TreeCore,
    component: ComponentObject,
    namingParent: NamingDirectory? = null,
) : ComponentNode(path, core, component, namingParent)
