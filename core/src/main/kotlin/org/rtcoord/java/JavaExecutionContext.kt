package org.rtcoord.java

import java.util.concurrent.CompletableFuture
import org.rtcoord.ExecutionContextView
import org.rtcoord.RtcException
import org.rtcoord.internal.JavaCalls

/**
 * An [ExecutionContextView] for Java callers: each operation blocking, and as a [CompletableFuture] (`...Async`).
 * [JavaComponent.executionContext] gives one; `new JavaExecutionContext(context)` drives a context at hand.
 */
public class JavaExecutionContext(
    /** The execution context this facade drives. */
    @get:JvmSynthetic public val context: ExecutionContextView
) {
    private val calls = JavaCalls(context.component.core.scope)

    /**
     * The rate in Hz.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class) public fun rate(): Double = calls.await { context.rate() }

    /** [rate], when done; it fails with what [rate] throws. */
    public fun rateAsync(): CompletableFuture<Double> = calls.future { context.rate() }

    /**
     * Sets the rate to [hz].
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun setRate(hz: Double): Unit = calls.await { context.setRate(hz) }

    /** [setRate], when done; it fails with what [setRate] throws. */
    public fun setRateAsync(hz: Double): CompletableFuture<Void?> = calls.done { context.setRate(hz) }

    /**
     * Whether the context is running.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun isRunning(): Boolean = calls.await { context.isRunning() }

    /** [isRunning], when done; it fails with what [isRunning] throws. */
    public fun isRunningAsync(): CompletableFuture<Boolean> = calls.future { context.isRunning() }

    /**
     * Makes [participant] take part in this context.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun add(participant: JavaComponent): Unit = calls.await { context.add(participant.node) }

    /** [add], when done; it fails with what [add] throws. */
    public fun addAsync(participant: JavaComponent): CompletableFuture<Void?> = calls.done {
        context.add(participant.node)
    }

    /**
     * Removes [participant] from this context.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun remove(participant: JavaComponent): Unit = calls.await { context.remove(participant.node) }

    /** [remove], when done; it fails with what [remove] throws. */
    public fun removeAsync(participant: JavaComponent): CompletableFuture<Void?> = calls.done {
        context.remove(participant.node)
    }

    override fun toString(): String = context.toString()
}
