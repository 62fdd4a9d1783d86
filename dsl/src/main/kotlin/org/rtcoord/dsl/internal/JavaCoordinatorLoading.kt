@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.internal

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.ThreadPoolExecutor
import java.util.concurrent.TimeUnit
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.asCoroutineDispatcher
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.internal.JavaCalls

/**
 * Loads coordinators for the dsl's Java facade, one at a time, on a thread of its own that ends a second after the last
 * load: a script's compilation takes seconds of CPU, which must not hold a tree's threads, and no thread may outlive
 * the work (in an OSGi framework it would hold the bundle's class loader).
 */
internal object JavaCoordinatorLoading {
    private val thread =
        ThreadPoolExecutor(0, 1, 1, TimeUnit.SECONDS, LinkedBlockingQueue()) { task ->
            Thread(task, "rtcoord-coordinator-loading").apply {
                isDaemon = true
                contextClassLoader = JavaCoordinatorLoading::class.java.classLoader
            }
        }
    // A supervisor: a script that fails to load must not cancel the loads after it.
    private val calls =
        JavaCalls(
            CoroutineScope(SupervisorJob() + thread.asCoroutineDispatcher() + CoroutineName("coordinator loading")),
            "coordinator loading",
        )

    /** The scripting host, made on first use: only scripts need it, and with it the Kotlin compiler. */
    private val host by lazy { ScriptHost() }

    /** Loads the coordinator at [script]: a compiled one ([CompiledCoordinator]) or a script, compiled first. */
    fun load(script: Path, args: List<String>, config: TreeConfig): CompletableFuture<Coordination> = calls.future {
        if (CompiledCoordinator.isCompiled(script)) CompiledCoordinator.load(script, args, config)
        else scriptHost(script).load(script, args, config)
    }

    /** Compiles the script at [script] into [jar] ([ScriptHost.compile]). */
    fun compile(script: Path, jar: Path): CompletableFuture<Void?> = calls.done {
        scriptHost(script).compile(script, jar)
    }

    /** Waits for [loading] as a blocking call of the facade does. */
    fun <T> await(loading: CompletableFuture<T>): T = calls.await(loading)

    /** A temporary file holding [text] under [name]. */
    fun scriptFile(name: String, text: String): Path {
        require(name.endsWith(".coord.kts")) { "a coordinator script's name ends in .coord.kts, not '$name'" }
        return Files.writeString(Files.createTempDirectory("rtcoord-script").resolve(name), text)
    }

    /** Deletes [script], a file of [scriptFile], and its directory. */
    fun delete(script: Path) {
        Files.deleteIfExists(script)
        Files.deleteIfExists(script.parent)
    }

    private fun scriptHost(script: Path): ScriptHost =
        try {
            host
        } catch (e: LinkageError) {
            throw ScriptFailure(
                listOf(
                    "$script: compiling a script needs the Kotlin compiler (kotlin-scripting-jvm-host), which is not on this class path (${e.message}): " +
                        "compile it ahead of time with `rtcoord compile $script -o NAME.jar` and load the jar"
                )
            )
        }
}
