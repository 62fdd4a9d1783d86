package org.rtcoord.internal

import java.util.concurrent.CancellationException
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ExecutionException
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.rtcoord.ClosedException
import org.rtcoord.InternalRtcoordApi

/**
 * How the Java facades (`org.rtcoord.java`) run a suspend operation: as a [CompletableFuture] in the [scope] of the
 * tree (or coordinator) named [subject], or blocking the caller until it is done and throwing what it threw, unwrapped,
 * with the caller's frames. Once the scope is closed, both fail with a [ClosedException]. Public for the dsl's Java
 * facade only.
 */
@InternalRtcoordApi
public class JavaCalls(private val scope: CoroutineScope, private val subject: String = "tree") {
    /** Runs [operation] in the scope; cancelling the future cancels it. */
    public fun <T> future(operation: suspend () -> T): CompletableFuture<T> {
        val result = CompletableFuture<T>()
        // The caller may give up: its remote calls must not hold it (see Remote).
        val job =
            scope.launch(AbandonableCalls) {
                try {
                    result.complete(operation())
                } catch (e: Throwable) {
                    result.completeExceptionally(closedOr(e))
                }
            }
        // Cancelled before it ran: by the scope's closing, which the caller learns as such.
        job.invokeOnCompletion { cause -> if (cause != null) result.completeExceptionally(closedOr(cause)) }
        result.whenComplete { _, _ -> if (result.isCancelled) job.cancel() }
        return result
    }

    /**
     * What to tell a Java caller of [failure]: that the scope is closed, when that is why (not kotlinx's
     * JobCancellationException).
     */
    private fun closedOr(failure: Throwable): Throwable =
        if (failure is CancellationException && !scope.isActive) ClosedException(subject) else failure

    /** [future] for an operation with no result: Java sees `CompletableFuture<Void>`. */
    public fun done(operation: suspend () -> Unit): CompletableFuture<Void?> = future {
        operation()
        null
    }

    /** Runs [operation] and waits for it. */
    @Throws(InterruptedException::class) public fun <T> await(operation: suspend () -> T): T = await(future(operation))

    /**
     * Waits for [running] and throws what it failed with, unwrapped. An interrupt cancels the operation and throws
     * [InterruptedException], as a blocking call in Java does.
     */
    @Throws(InterruptedException::class)
    public fun <T> await(running: CompletableFuture<T>): T {
        try {
            return running.get()
        } catch (e: ExecutionException) {
            throw (e.cause ?: e).withCallerFrames()
        } catch (e: InterruptedException) {
            // The caller gave up: the operation stops too (its remote call returns at once, see Remote).
            running.cancel(true)
            throw e
        }
    }

    /**
     * Appends the waiting caller's frames to a failure that happened on one of the tree's threads, whose own frames
     * show only the coroutine: after a [BOUNDARY], which a failure thrown again (a cached one) moves instead of piling
     * up.
     */
    private fun Throwable.withCallerFrames(): Throwable = apply {
        val own = stackTrace.takeWhile { it != BOUNDARY }
        val caller = Throwable().stackTrace.dropWhile { it.className == JavaCalls::class.java.name }
        stackTrace = (own + BOUNDARY + caller).toTypedArray()
    }

    private companion object {
        val BOUNDARY = StackTraceElement("rtcoord", "awaited", "by the caller's thread", -1)
    }
}
