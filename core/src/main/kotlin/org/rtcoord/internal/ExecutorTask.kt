package org.rtcoord.internal

import java.util.concurrent.Executor
import java.util.concurrent.RejectedExecutionException
import kotlin.coroutines.resume
import kotlin.coroutines.resumeWithException
import kotlinx.coroutines.suspendCancellableCoroutine
import org.rtcoord.InternalRtcoordApi

/**
 * Runs [task] on this [Executor], the one a Java caller named for its listener (SWT: `display::asyncExec`), and
 * suspends until it has run; returns what it returned and throws what it threw. A task still waiting in the executor
 * when the caller is cancelled does not run.
 *
 * An executor that refuses the task (SWT after its display is disposed, a pool that was shut down) makes the call throw
 * that [RejectedExecutionException], naming the executor, for the caller's failure handler to hear of. kotlinx's
 * `Executor.asCoroutineDispatcher()` is not used: on a refusal it cancels the coroutine and runs the task on kotlinx's
 * own shared threads, so the delivery ends in silence and the listener runs where its caller did not want it. Public
 * for the dsl's Java facade only.
 */
@InternalRtcoordApi
public suspend fun <T> Executor.runTask(task: () -> T): T = suspendCancellableCoroutine { call ->
    val executor = this
    try {
        execute {
            if (!call.isActive) return@execute
            val result =
                try {
                    Result.success(task())
                } catch (e: Throwable) {
                    Result.failure(e)
                }
            result.fold({ call.resume(it) }, { call.resumeWithException(it) })
        }
    } catch (e: RejectedExecutionException) {
        call.resumeWithException(
            RejectedExecutionException(
                "executor $executor refused the listener's task: ${e.message ?: "no reason given"}",
                e,
            )
        )
    }
}
