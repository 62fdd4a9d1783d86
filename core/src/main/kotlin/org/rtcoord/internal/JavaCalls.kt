package org.rtcoord.internal

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.future.future
import java.util.concurrent.CancellationException
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ExecutionException

/**
 * How the Java facades (`org.rtcoord.java`) run a suspend operation: as a [CompletableFuture] in the
 * tree's [scope], or blocking the caller until it is done and throwing what it threw, unwrapped.
 */
internal class JavaCalls(private val scope: CoroutineScope) {
    fun <T> future(operation: suspend () -> T): CompletableFuture<T> = scope.future { operation() }

    /** [future] for an operation with no result: Java sees `CompletableFuture<Void>`. */
    fun done(operation: suspend () -> Unit): CompletableFuture<Void?> = scope.future { operation(); null }

    fun <T> await(operation: suspend () -> T): T {
        val running = future(operation)
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
