@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.internal

import java.util.AbstractMap.SimpleImmutableEntry
import java.util.concurrent.Executor
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.atomic.AtomicBoolean
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.merge
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import org.rtcoord.dsl.Coordinator
import org.rtcoord.internal.JavaCalls
import org.rtcoord.internal.reportListenerFailure
import org.rtcoord.internal.runTask
import org.rtcoord.internal.treeScope
import org.slf4j.LoggerFactory

/**
 * What the dsl's Java facade runs for one [coordinator]: its blocking and future calls, and the deliveries of its
 * `subscribe...` listeners, in one scope, a child of [tree]'s on the tree's threads: closing the coordinator ends them,
 * and nothing runs on kotlinx's shared threads.
 */
internal class JavaCoordinatorRun(private val coordinator: Coordinator, private val tree: RtcTree) : AutoCloseable {
    private val scope =
        CoroutineScope(
            tree.treeScope().coroutineContext +
                SupervisorJob(tree.treeScope().coroutineContext.job) +
                CoroutineName("java coordinator ${coordinator.name}")
        )

    /** The facade's blocking and future calls. */
    val calls = JavaCalls(scope, "coordinator ${coordinator.name}")

    /**
     * Delivers the values of [sources] (each with its key) to [deliver] on [executor], one at a time: the current one
     * of each, then each change. What [listener] throws, and each refusal of [executor], goes to the tree's listener
     * failure handler with the change (key and value), as an event listener's does, and the next value is delivered; a
     * refusal is logged too, once, as every later task will likely be refused as well.
     */
    fun <T> follow(
        executor: Executor,
        listener: Any,
        what: String,
        sources: List<Pair<String, StateFlow<T>>>,
        deliver: (String, T) -> Unit,
    ): Subscription {
        val refusalLogged = AtomicBoolean()
        val job =
            scope.launch(CoroutineName("java coordinator ${coordinator.name}: $what")) {
                sources
                    .map { (key, flow) -> flow.map { key to it } }
                    .merge()
                    .collect { (key, value) ->
                        try {
                            executor.runTask { deliver(key, value) }
                        } catch (e: CancellationException) {
                            throw e
                        } catch (e: Throwable) {
                            if (e is RejectedExecutionException && refusalLogged.compareAndSet(false, true)) {
                                log.warn(
                                    "coordinator {}: listener {} of its {} gets no more changes: {} (each one refused goes to the tree's listener failure handler)",
                                    coordinator.name,
                                    listener,
                                    what,
                                    e.message,
                                )
                            }
                            tree.reportListenerFailure(listener, SimpleImmutableEntry(key, value), e)
                        }
                    }
            }
        return Subscription { job.cancel() }
    }

    override fun close() {
        coordinator.close()
        scope.cancel()
    }

    private companion object {
        val log = LoggerFactory.getLogger(JavaCoordinatorRun::class.java)
    }
}
