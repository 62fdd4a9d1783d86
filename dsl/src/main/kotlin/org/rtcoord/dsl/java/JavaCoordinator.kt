@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.java

import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.Executor
import java.util.function.BiConsumer
import java.util.function.Consumer
import java.util.function.IntConsumer
import org.jspecify.annotations.Nullable
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.RuleActivity
import org.rtcoord.dsl.SupervisorActivity
import org.rtcoord.dsl.internal.JavaCoordinatorLoading
import org.rtcoord.dsl.internal.JavaCoordinatorRun
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.java.JavaTree

/**
 * A coordinator for Java callers: a `.coord.kts` script, or one compiled ahead of time into a jar (`rtcoord compile
 * SCRIPT.coord.kts -o NAME.jar`), which loads without the Kotlin compiler, as in an Eclipse plug-in. Started and
 * stopped without coroutines; each operation is blocking, and a [CompletableFuture] (`...Async`) too. It runs on its
 * tree's threads and ends with it.
 *
 * ```java
 * try (JavaCoordinator coordinator = JavaCoordinator.load(tree, Path.of("restart.jar"))) {
 *     coordinator.start();
 *     ...
 * }
 * ```
 */
public class JavaCoordinator
private constructor(
    /** The coordinator this facade drives, for Kotlin code: Java follows it through the `subscribe...` listeners. */
    @get:JvmSynthetic public val coordinator: Coordinator,
    tree: JavaTree,
) : AutoCloseable {
    private val run = JavaCoordinatorRun(coordinator, tree.tree)

    /**
     * Subscribes the rules and starts timers, machines and supervisors (see [Coordinator.start]).
     *
     * @throws RtcException when a rule's target does not exist or is ambiguous; nothing is left running.
     * @throws org.rtcoord.ClosedException once the coordinator (or its tree) is closed.
     * @throws InterruptedException when the calling thread is interrupted while it waits; the start is cancelled.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun start() {
        run.calls.await { coordinator.start() }
    }

    /** [start], when done; it fails as [start] throws. */
    public fun startAsync(): CompletableFuture<Void?> = run.calls.done { coordinator.start() }

    /**
     * Calls [listener] on [executor] with each rule's description and status (see [RuleActivity]): the current one of
     * every rule at once, then each change, one at a time. Close the [Subscription] to stop; closing the coordinator
     * stops it too. What the listener throws, and each refusal of [executor], go to the tree's
     * [org.rtcoord.TreeConfig.listenerFailures] with the listener and the change (a `Map.Entry` of the rule's
     * description and its status); a refusal is logged too, once. The next change is delivered all the same.
     */
    public fun subscribeRules(executor: Executor, listener: BiConsumer<String, RuleActivity.Status>): Subscription =
        run.follow(executor, listener, "rules", coordinator.rules.map { rule -> rule.description to rule.status }) {
            description,
            status ->
            listener.accept(description, status)
        }

    /**
     * Calls [listener] on [executor] with each mode machine's name and active mode (null before it has one): the
     * current mode of every machine at once, then each change. Close the [Subscription] to stop. Failures go to the
     * tree's listener failure handler, as for [subscribeRules].
     */
    public fun subscribeModes(executor: Executor, listener: BiConsumer<String, @Nullable String?>): Subscription =
        run.follow(executor, listener, "modes", coordinator.machines.map { machine -> machine.name to machine.mode }) {
            name,
            mode ->
            listener.accept(name, mode)
        }

    /**
     * Calls [listener] on [executor] with each supervisor's name and status (see [SupervisorActivity]): children,
     * restarts, the back-off it waits out, its escalation; the status of every supervisor at once, before [start] too
     * (nothing done yet), then each change. Close the [Subscription] to stop. Failures go to the tree's listener
     * failure handler, as for [subscribeRules].
     */
    public fun subscribeSupervisors(
        executor: Executor,
        listener: BiConsumer<String, SupervisorActivity.Status>,
    ): Subscription =
        run.follow(
            executor,
            listener,
            "supervisors",
            coordinator.supervision.map { supervisor -> supervisor.name to supervisor.status },
        ) { name, status ->
            listener.accept(name, status)
        }

    /**
     * Calls [listener] on [executor] with how many handler runs have failed: the count now, then each change. Failures
     * go to the tree's listener failure handler, as for [subscribeRules].
     */
    public fun subscribeFailures(executor: Executor, listener: IntConsumer): Subscription =
        run.follow(executor, listener, "failures", listOf("failures" to coordinator.failureCounts)) { _, count ->
            listener.accept(count)
        }

    /**
     * Stops the coordinator: cancels its handlers and its listeners' deliveries and detaches its observers. Idempotent.
     */
    override fun close() {
        run.close()
    }

    /** How Java callers load a coordinator. */
    private companion object {
        /**
         * Loads the coordinator at [script] with [args], for [tree]; [log] receives its log lines. A `.jar` is a
         * coordinator compiled ahead of time ([CompiledCoordinator]): it needs no Kotlin compiler. A script is compiled
         * (or taken from the cache) first, which needs the compiler, as the `rtcoord-dsl` artifact has it and the OSGi
         * bundle has not. The load runs on a thread of its own, which ends with it.
         *
         * @throws ScriptFailure when the script does not compile or its body throws (each problem as `file:line:col:
         *   message`), when the jar is not a compiled coordinator (naming its path) or was compiled by another rtcoord
         *   version (naming both), or when a script needs the compiler and it is absent.
         * @throws InterruptedException when the calling thread is interrupted while it waits; the load is cancelled.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ScriptFailure::class, InterruptedException::class)
        public fun load(
            tree: JavaTree,
            script: Path,
            args: List<String> = emptyList(),
            log: Consumer<String> = Consumer {},
        ): JavaCoordinator = JavaCoordinatorLoading.await(loadAsync(tree, script, args, log))

        /** [load], when done; it fails as [load] throws. */
        @JvmStatic
        @JvmOverloads
        public fun loadAsync(
            tree: JavaTree,
            script: Path,
            args: List<String> = emptyList(),
            log: Consumer<String> = Consumer {},
        ): CompletableFuture<JavaCoordinator> =
            JavaCoordinatorLoading.load(script, args, tree.tree.config).thenApply { coordination ->
                JavaCoordinator(Coordinator(tree.tree, coordination, null) { log.accept(it) }, tree)
            }

        /**
         * Compiles the script at [script] into [jar]: a coordinator [load] runs without the Kotlin compiler, as
         * `rtcoord compile` makes it. Compiling needs the compiler, which the `rtcoord-dsl` artifact has and the OSGi
         * bundle has not.
         *
         * @throws ScriptFailure when the script does not compile (each problem as `file:line:col: message`), when [jar]
         *   cannot be written, or when the compiler is absent.
         * @throws InterruptedException when the calling thread is interrupted while it waits; the compilation is
         *   cancelled.
         */
        @JvmStatic
        @Throws(ScriptFailure::class, InterruptedException::class)
        public fun compile(script: Path, jar: Path) {
            JavaCoordinatorLoading.await(JavaCoordinatorLoading.compile(script, jar))
        }

        /**
         * [load] for a script given as its [text] under the file [name] (`restart.coord.kts`), which problems are
         * reported against. The text is compiled from a temporary directory, so file names in it must be absolute.
         * Needs the Kotlin compiler.
         *
         * @throws ScriptFailure as [load] does.
         * @throws IllegalArgumentException when [name] does not end in `.coord.kts`.
         * @throws java.io.IOException when the temporary file cannot be written.
         * @throws InterruptedException when the calling thread is interrupted while it waits.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ScriptFailure::class, java.io.IOException::class, InterruptedException::class)
        public fun fromText(
            tree: JavaTree,
            name: String,
            text: String,
            args: List<String> = emptyList(),
            log: Consumer<String> = Consumer {},
        ): JavaCoordinator {
            val script = JavaCoordinatorLoading.scriptFile(name, text)
            try {
                return load(tree, script, args, log)
            } catch (e: ScriptFailure) {
                // Problems name the script as the caller did, not the temporary file it was compiled from.
                throw ScriptFailure(e.problems.map { it.replace(script.toString(), name) })
            } finally {
                JavaCoordinatorLoading.delete(script)
            }
        }
    }
}
