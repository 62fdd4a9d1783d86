package org.rtcoord.internal

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.future.future
import org.rtcoord.InternalRtcoordApi
import java.util.concurrent.CancellationException
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ExecutionException

/**
 * How the Java facades (`org.rtcoord.java`) run a suspend operation: as a [CompletableFuture] in the
 * tree's [scope], or blocking the caller until it is done and throwing what it threw, unwrapped. Public
 * for the dsl's Java facade only.
 */
@InternalRtcoordApi
public class JavaCalls(private val scope: CoroutineScope) {
    /** Runs [operation] in the scope. */
    public fun <T> future(operation: suspend () -> T): CompletableFuture<T> = scope.future { operation() }

    /** [future] for an operation with no result: Java sees `CompletableFuture<Void>`. */
    public fun done(operation: suspend () -> Unit): CompletableFuture<Void?> = scope.future { operation(); null }

    /** Runs [operation] and waits for it. */
    public fun <T> await(operation: suspend () -> T): T = await(future(operation))

    /** Waits for [running] and throws what it failed with, unwrapped; an interrupt cancels it. */
    public fun <T> await(running: CompletableFuture<T>): T {
        try {
            return running.get()
        } catch (e: ExecutionException) {
            throw e.cause ?: e
        } catch (e: InterruptedException) {
            // The caller gave up: the operation stops too, and the thread stays interrupted for its owner.
            running.cancel(true)
            Thread.currentThread().interrupt()
            throw CancellationException("interrupted while waiting for the operation").apply { initCause(e) }
        }
    }
}
