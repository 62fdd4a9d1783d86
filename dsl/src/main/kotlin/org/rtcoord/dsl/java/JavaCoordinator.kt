@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.java

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.merge
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.ClosedException
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.RuleActivity
import org.rtcoord.dsl.SupervisorActivity
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.internal.JavaCalls
import org.rtcoord.java.JavaTree
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.Executor
import java.util.function.BiConsumer
import java.util.function.Consumer
import java.util.function.IntConsumer

/**
 * A `.coord.kts` coordinator for Java callers: loaded from a file or from its text, started and stopped
 * without coroutines. Each operation is blocking, and a [CompletableFuture] (`...Async`) too.
 *
 * ```java
 * try (JavaCoordinator coordinator = JavaCoordinator.load(tree, Path.of("restart.coord.kts"))) {
 *     coordinator.start();
 *     ...
 * }
 * ```
 */
public class JavaCoordinator private constructor(
    /** The coordinator this facade drives, for Kotlin code: Java follows it through the `subscribe...` listeners. */
    @get:JvmSynthetic public val coordinator: Coordinator,
) : AutoCloseable {
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("java coordinator"))
    private val calls = JavaCalls(scope, "coordinator ${coordinator.name}")

    /** Subscribes the rules and starts timers, machines and supervisors (see [Coordinator.start]). */
    @Throws(RtcException::class, InterruptedException::class)
    public fun start() {
        calls.await { coordinator.start() }
    }

    /** [start], when done. */
    public fun startAsync(): CompletableFuture<Void?> = calls.done { coordinator.start() }

    /**
     * Calls [listener] on [executor] with each rule's description and status (see [RuleActivity]): the
     * current one of every rule at once, then each change, one at a time. Close the [Subscription] to stop;
     * closing the coordinator stops it too.
     */
    public fun subscribeRules(executor: Executor, listener: BiConsumer<String, RuleActivity.Status>): Subscription =
        follow(executor, coordinator.rules.map { rule -> rule.status.map { rule.description to it } }) { (description, status) -> listener.accept(description, status) }

    /**
     * Calls [listener] on [executor] with each mode machine's name and active mode (null before it has
     * one): the current mode of every machine at once, then each change. Close the [Subscription] to stop.
     */
    public fun subscribeModes(executor: Executor, listener: BiConsumer<String, String?>): Subscription =
        follow(executor, coordinator.machines.map { machine -> machine.mode.map { machine.name to it } }) { (name, mode) -> listener.accept(name, mode) }

    /**
     * Calls [listener] on [executor] with each supervisor's name and status (see [SupervisorActivity]):
     * children, restarts, the back-off it waits out, its escalation. Supervisors start with the
     * coordinator: subscribe after [start]; before it there are none to follow. Close the [Subscription] to stop.
     */
    public fun subscribeSupervisors(executor: Executor, listener: BiConsumer<String, SupervisorActivity.Status>): Subscription =
        follow(executor, coordinator.supervision.map { supervisor -> supervisor.status.map { supervisor.name to it } }) { (name, status) -> listener.accept(name, status) }

    /** Calls [listener] on [executor] with how many handler runs have failed: the count now, then each change. */
    public fun subscribeFailures(executor: Executor, listener: IntConsumer): Subscription =
        follow(executor, listOf(coordinator.failureCounts)) { listener.accept(it) }

    private fun <T> follow(executor: Executor, flows: List<Flow<T>>, deliver: (T) -> Unit): Subscription {
        val dispatcher = executor.asCoroutineDispatcher()
        val job = scope.launch { flows.merge().collect { withContext(dispatcher) { deliver(it) } } }
        return Subscription { job.cancel() }
    }

    /** Stops the coordinator: cancels its handlers and detaches its observers. Idempotent. */
    override fun close() {
        coordinator.close()
        scope.cancel()
    }

    /** How Java callers load a coordinator. */
    public companion object {
        private val host by lazy { ScriptHost() }
        // A supervisor: a script that fails to load must not cancel the loads after it.
        private val loading = JavaCalls(CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("java coordinator loading")), "coordinator loading")

        /**
         * Compiles (or takes from the cache) and evaluates the script at [script] with [args], for [tree];
         * [log] receives its log lines. Throws [ScriptFailure] naming each problem.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ScriptFailure::class, InterruptedException::class)
        public fun load(tree: JavaTree, script: Path, args: List<String> = emptyList(), log: Consumer<String> = Consumer {}): JavaCoordinator =
            loading.await(loadAsync(tree, script, args, log))

        /** [load], when done. */
        @JvmStatic
        @JvmOverloads
        public fun loadAsync(tree: JavaTree, script: Path, args: List<String> = emptyList(), log: Consumer<String> = Consumer {}): CompletableFuture<JavaCoordinator> =
            loading.future {
                val coordination = host.load(script, args, tree.tree.config)
                JavaCoordinator(Coordinator(tree.tree, coordination, null as EventOptions?) { log.accept(it) })
            }

        /**
         * [load] for a script given as its [text] under the file [name] (`restart.coord.kts`), which
         * problems are reported against. The text is compiled from a temporary directory, so file names in
         * it must be absolute.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ScriptFailure::class, InterruptedException::class)
        public fun fromText(tree: JavaTree, name: String, text: String, args: List<String> = emptyList(), log: Consumer<String> = Consumer {}): JavaCoordinator {
            require(name.endsWith(".coord.kts")) { "a coordinator script's name ends in .coord.kts, not '$name'" }
            val directory = Files.createTempDirectory("rtcoord-script")
            val script = Files.writeString(directory.resolve(name), text)
            try {
                return load(tree, script, args, log)
            } catch (e: ScriptFailure) {
                // Problems name the script as the caller did, not the temporary file it was compiled from.
                throw ScriptFailure(e.problems.map { it.replace(script.toString(), name) })
            } finally {
                Files.delete(script)
                Files.delete(directory)
            }
        }
    }
}
