package org.rtcoord.java

import java.time.Duration
import java.util.concurrent.CompletableFuture
import kotlin.time.toKotlinDuration
import org.jspecify.annotations.Nullable
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ComponentSummary
import org.rtcoord.Composition
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle
import org.rtcoord.RtcException
import org.rtcoord.TransitionOutcome
import org.rtcoord.internal.JavaCalls

/**
 * A [ComponentNode] for Java callers: each operation blocking, and as a [CompletableFuture] (`...Async`). A lifecycle
 * operation acts on [context] (the first owned context unless given) and waits for the state within [deadline] (the
 * tree's call deadline unless given), as [ComponentNode.activate] does.
 *
 * [JavaTree.component] finds one by path; `new JavaComponent(node)` drives a node at hand: an event's source
 * ([org.rtcoord.StateChanged.source]), a snapshot's [org.rtcoord.ComponentEntry.node].
 */
public class JavaComponent(
    /** The component this facade drives. */
    @get:JvmSynthetic public val node: ComponentNode
) {
    private val calls = JavaCalls(node.core.scope)

    /**
     * The latest snapshot, read now if there is none yet.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun snapshot(): ComponentSnapshot = calls.await { node.snapshot() }

    /** [snapshot], when done; it fails with what [snapshot] throws. */
    public fun snapshotAsync(): CompletableFuture<ComponentSnapshot> = calls.future { node.snapshot() }

    /**
     * Reads the component again (see [ComponentNode.refresh]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun refresh(): Unit = calls.await { node.refresh() }

    /** [refresh], when done; it fails with what [refresh] throws. */
    public fun refreshAsync(): CompletableFuture<Void?> = calls.done { node.refresh() }

    /**
     * What a listing shows of the component, read now (see [ComponentNode.refreshSummary]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun refreshSummary(): ComponentSummary = calls.await { node.refreshSummary() }

    /** [refreshSummary], when done; it fails with what [refreshSummary] throws. */
    public fun refreshSummaryAsync(): CompletableFuture<ComponentSummary> = calls.future { node.refreshSummary() }

    /**
     * The component's state in [context], read now.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun state(context: ContextSelector = ContextSelector.Handle(0)): LifeCycle = calls.await {
        node.state(context)
    }

    /** [state], when done; it fails with what [state] throws. */
    @JvmOverloads
    public fun stateAsync(context: ContextSelector = ContextSelector.Handle(0)): CompletableFuture<LifeCycle> =
        calls.future {
            node.state(context)
        }

    /**
     * Activates the component and waits until it is ACTIVE; returns how it got there: [TransitionOutcome.isSlow] when
     * the state came only after its context had answered that it did not.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun activate(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): TransitionOutcome = calls.await { node.activate(context, deadline?.toKotlinDuration()) }

    /** [activate], when done; it fails with what [activate] throws. */
    @JvmOverloads
    public fun activateAsync(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): CompletableFuture<TransitionOutcome> = calls.future { node.activate(context, deadline?.toKotlinDuration()) }

    /**
     * Deactivates the component and waits until it is INACTIVE; returns how it got there: [TransitionOutcome.isSlow]
     * when the state came only after its context had answered that it did not.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun deactivate(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): TransitionOutcome = calls.await { node.deactivate(context, deadline?.toKotlinDuration()) }

    /** [deactivate], when done; it fails with what [deactivate] throws. */
    @JvmOverloads
    public fun deactivateAsync(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): CompletableFuture<TransitionOutcome> = calls.future { node.deactivate(context, deadline?.toKotlinDuration()) }

    /**
     * Resets the component from ERROR and waits until it is INACTIVE; returns how it got there:
     * [TransitionOutcome.isSlow] when the state came only after its context had answered that it did not.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun reset(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): TransitionOutcome = calls.await { node.reset(context, deadline?.toKotlinDuration()) }

    /** [reset], when done; it fails with what [reset] throws. */
    @JvmOverloads
    public fun resetAsync(
        context: ContextSelector = ContextSelector.Handle(0),
        deadline: @Nullable Duration? = null,
    ): CompletableFuture<TransitionOutcome> = calls.future { node.reset(context, deadline?.toKotlinDuration()) }

    /**
     * Asks the component to exit and waits until naming no longer shows it (see [ComponentNode.exit]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class) public fun exit(): Unit = calls.await { node.exit() }

    /** [exit], when done; it fails with what [exit] throws. */
    public fun exitAsync(): CompletableFuture<Void?> = calls.done { node.exit() }

    /**
     * Whether the component is a composite and whether it is part of one, read now.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun composition(): Composition = calls.await { node.composition() }

    /** [composition], when done; it fails with what [composition] throws. */
    public fun compositionAsync(): CompletableFuture<Composition> = calls.future { node.composition() }

    /**
     * The port named [name] (without the instance prefix).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun port(name: String): JavaPort = calls.await { JavaPort(node.port(name)) }

    /** [port], when done; it fails with what [port] throws. */
    public fun portAsync(name: String): CompletableFuture<JavaPort> = calls.future { JavaPort(node.port(name)) }

    /**
     * Disconnects every connection of every port.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun disconnectAll(): Unit = calls.await { node.disconnectAll() }

    /** [disconnectAll], when done; it fails with what [disconnectAll] throws. */
    public fun disconnectAllAsync(): CompletableFuture<Void?> = calls.done { node.disconnectAll() }

    /**
     * The execution context [context] of this component.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun executionContext(context: ContextSelector = ContextSelector.Handle(0)): JavaExecutionContext =
        calls.await {
            JavaExecutionContext(node.executionContext(context))
        }

    /** [executionContext], when done; it fails with what [executionContext] throws. */
    @JvmOverloads
    public fun executionContextAsync(
        context: ContextSelector = ContextSelector.Handle(0)
    ): CompletableFuture<JavaExecutionContext> = calls.future { JavaExecutionContext(node.executionContext(context)) }

    /**
     * The configuration sets, read now if they never were.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun configuration(): ConfigurationSnapshot = calls.await { node.configuration() }

    /** [configuration], when done; it fails with what [configuration] throws. */
    public fun configurationAsync(): CompletableFuture<ConfigurationSnapshot> = calls.future { node.configuration() }

    /**
     * Sets [parameter] to [value] in configuration set [set] (the active one when null); returns a warning when the
     * value is outside the parameter's constraint, which [strict] refuses instead; see [ComponentNode.setParameters].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun setParameter(
        parameter: String,
        value: String,
        set: @Nullable String? = null,
        strict: Boolean = false,
    ): List<String> = calls.await { node.setParameter(parameter, value, set, strict) }

    /** [setParameter], when done; it fails with what [setParameter] throws. */
    @JvmOverloads
    public fun setParameterAsync(
        parameter: String,
        value: String,
        set: @Nullable String? = null,
        strict: Boolean = false,
    ): CompletableFuture<List<String>> = calls.future { node.setParameter(parameter, value, set, strict) }

    /**
     * Sets several parameters of configuration set [set] (the active one when null) at once; returns one warning per
     * value outside its constraint, which [strict] refuses instead; see [ComponentNode.setParameters].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun setParameters(
        values: Map<String, String>,
        set: @Nullable String? = null,
        strict: Boolean = false,
    ): List<String> = calls.await { node.setParameters(values, set, strict) }

    /** [setParameters], when done; it fails with what [setParameters] throws. */
    @JvmOverloads
    public fun setParametersAsync(
        values: Map<String, String>,
        set: @Nullable String? = null,
        strict: Boolean = false,
    ): CompletableFuture<List<String>> = calls.future { node.setParameters(values, set, strict) }

    /**
     * Makes configuration set [id] the active one.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun activateConfigurationSet(id: String): Unit = calls.await { node.activateConfigurationSet(id) }

    /** [activateConfigurationSet], when done; it fails with what [activateConfigurationSet] throws. */
    public fun activateConfigurationSetAsync(id: String): CompletableFuture<Void?> = calls.done {
        node.activateConfigurationSet(id)
    }

    /**
     * Adds configuration set [id] holding [values].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun addConfigurationSet(id: String, values: Map<String, String>): Unit = calls.await {
        node.addConfigurationSet(id, values)
    }

    /** [addConfigurationSet], when done; it fails with what [addConfigurationSet] throws. */
    public fun addConfigurationSetAsync(id: String, values: Map<String, String>): CompletableFuture<Void?> =
        calls.done {
            node.addConfigurationSet(id, values)
        }

    /**
     * Removes configuration set [id].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun removeConfigurationSet(id: String): Unit = calls.await { node.removeConfigurationSet(id) }

    /** [removeConfigurationSet], when done; it fails with what [removeConfigurationSet] throws. */
    public fun removeConfigurationSetAsync(id: String): CompletableFuture<Void?> = calls.done {
        node.removeConfigurationSet(id)
    }

    override fun toString(): String = node.toString()
}
