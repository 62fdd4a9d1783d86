@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.java

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcException
import org.rtcoord.dsl.runtime.Coordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.internal.JavaCalls
import org.rtcoord.java.JavaTree
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.function.Consumer

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
    /** The coordinator this facade drives: its rules, machines and failures are readable from Java. */
    public val coordinator: Coordinator,
) : AutoCloseable {
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("java coordinator"))
    private val calls = JavaCalls(scope)

    /** Subscribes the rules and starts timers, machines and supervisors (see [Coordinator.start]). */
    @Throws(RtcException::class)
    public fun start() {
        calls.await { coordinator.start() }
    }

    /** [start], when done. */
    public fun startAsync(): CompletableFuture<Void?> = calls.done { coordinator.start() }

    /** Stops the coordinator: cancels its handlers and detaches its observers. Idempotent. */
    override fun close() {
        coordinator.close()
        scope.cancel()
    }

    /** How Java callers load a coordinator. */
    public companion object {
        private val host by lazy { ScriptHost() }
        // A supervisor: a script that fails to load must not cancel the loads after it.
        private val loading = JavaCalls(CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("java coordinator loading")))

        /**
         * Compiles (or takes from the cache) and evaluates the script at [script] with [args], for [tree];
         * [log] receives its log lines. Throws [ScriptFailure] naming each problem.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ScriptFailure::class)
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
        @Throws(ScriptFailure::class)
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
