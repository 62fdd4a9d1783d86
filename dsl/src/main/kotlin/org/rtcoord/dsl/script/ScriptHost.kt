@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.script

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.script.experimental.api.CompiledScript
import kotlin.script.experimental.api.ResultValue
import kotlin.script.experimental.api.ResultWithDiagnostics
import kotlin.script.experimental.api.ScriptDiagnostic
import kotlin.script.experimental.api.ScriptEvaluationConfiguration
import kotlin.script.experimental.api.constructorArgs
import kotlin.script.experimental.host.toScriptSource
import kotlin.script.experimental.jvm.BasicJvmScriptEvaluator
import kotlin.script.experimental.jvm.baseClassLoader
import kotlin.script.experimental.jvm.jvm
import kotlin.script.experimental.jvmhost.JvmScriptCompiler
import kotlin.script.experimental.jvmhost.createJvmCompilationConfigurationFromTemplate
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination

/**
 * Compiles and evaluates `*.coord.kts` coordinators with the embedded Kotlin compiler. Compiled scripts are kept in
 * [cacheDirectory] by a hash of their text and of the compiler and DSL they were built with, so an unchanged script
 * starts without compiling. Problems come back as `file:line:col: message` lines.
 */
public class ScriptHost(private val cacheDirectory: Path? = defaultCacheDirectory()) {
    /**
     * Made when a script is first compiled: it reads the template's annotations with Kotlin's full reflection, which a
     * cached script never starts.
     */
    private val compilation by lazy { createJvmCompilationConfigurationFromTemplate<CoordinatorScript>() }
    /**
     * Made when a script is first compiled: a cached script loads without the compiler's classes, so `rtcoord run` has
     * no compiler on its class path (the launcher's, bin/rtcoord).
     */
    private val compiler by lazy {
        JvmScriptCompiler(CompiledScripts.host(cacheDirectory, CoordinatorScript::class.java))
    }
    private val evaluator by lazy { BasicJvmScriptEvaluator() }
    /** Without the cache: a script taken from it is only a jar of classes, without the compiler's output to write. */
    private val fresh by lazy { JvmScriptCompiler(CompiledScripts.host(null, CoordinatorScript::class.java)) }

    /**
     * Whether [script], as its file is now, was compiled before and is kept in the cache: [load] starts it without the
     * Kotlin compiler. False without a cache, for a file that cannot be read, and for a kept jar cut short. A rebuilt
     * DSL keeps its scripts apart ([CompiledScripts.host]).
     */
    public fun isCached(script: Path): Boolean =
        try {
            kept(script) != null
        } catch (e: IOException) {
            false
        }

    /** Compiles [script]; returns its errors (none when it compiles). */
    public suspend fun check(script: Path): List<String> =
        when (val result = compile(script)) {
            is ResultWithDiagnostics.Success -> emptyList()
            is ResultWithDiagnostics.Failure -> ScriptProblems.of(script, result.reports)
        }

    /**
     * Compiles (or takes from the cache) and evaluates [script] with [args], the host running it on [host]: returns
     * what it declared. File names in the script are relative to the script's directory. A `.jar` is a coordinator
     * compiled ahead of time, loaded without compiling ([CompiledCoordinator.load]). Throws [ScriptFailure] when it
     * does not compile or its body throws.
     */
    public suspend fun load(
        script: Path,
        args: List<String> = emptyList(),
        host: TreeConfig = TreeConfig(),
    ): Coordination {
        if (CompiledCoordinator.isCompiled(script)) return CompiledCoordinator.load(script, args, host)
        kept(script)?.let { jar ->
            CompiledCoordinator.loadKept(jar, script, args, host)?.let {
                return it
            }
            // Not a script this rtcoord can run: the compiler would take it from the cache as it is.
            Files.deleteIfExists(jar)
        }
        val compiled =
            when (val result = compile(script)) {
                is ResultWithDiagnostics.Success -> result.value
                is ResultWithDiagnostics.Failure -> throw ScriptFailure(ScriptProblems.of(script, result.reports))
            }
        val evaluation = ScriptEvaluationConfiguration {
            constructorArgs(args.toTypedArray(), host, script.toAbsolutePath().parent, script.fileName.toString())
            jvm { baseClassLoader(ScriptHost::class.java.classLoader) }
        }
        return when (val result = evaluator(compiled, evaluation)) {
            is ResultWithDiagnostics.Failure -> throw ScriptFailure(ScriptProblems.of(script, result.reports))
            is ResultWithDiagnostics.Success ->
                when (val value = result.value.returnValue) {
                    is ResultValue.Error ->
                        throw ScriptFailure(listOf(ScriptProblems.thrown(script.toString(), value.error)))
                    else ->
                        value.scriptInstance as? Coordination
                            ?: throw ScriptFailure(
                                listOf("${script.fileName}:1:1: the script did not produce a coordinator")
                            )
                }
        }
    }

    /**
     * Compiles [script] into [jar], a coordinator that runs without the Kotlin compiler ([CompiledCoordinator]): in an
     * Eclipse plug-in through rtcoord's OSGi bundle, or with `rtcoord run NAME.jar`. Compiles afresh, whatever the
     * cache holds. Throws [ScriptFailure] when it does not compile or [jar] cannot be written.
     */
    public suspend fun compile(script: Path, jar: Path) {
        val compiled =
            when (val result = compile(script, by = fresh)) {
                is ResultWithDiagnostics.Success -> result.value
                is ResultWithDiagnostics.Failure -> throw ScriptFailure(ScriptProblems.of(script, result.reports))
            }
        CompiledCoordinatorJar.write(compiled, Files.readString(script), script.fileName.toString(), jar)
    }

    /** The jar the cache keeps [script] in, compiled from its text as it is now; null when it keeps none. */
    private fun kept(script: Path): Path? =
        if (cacheDirectory == null || !Files.isRegularFile(script)) null
        else CompiledScripts.kept(cacheDirectory, script.toFile().toScriptSource(), CoordinatorScript::class.java)

    private suspend fun compile(script: Path, by: JvmScriptCompiler = compiler): ResultWithDiagnostics<CompiledScript> {
        if (!Files.isRegularFile(script))
            return ResultWithDiagnostics.Failure(
                ScriptDiagnostic(ScriptDiagnostic.unspecifiedError, "no such file", sourcePath = script.toString())
            )
        return by(script.toFile().toScriptSource(), compilation)
    }

    public companion object {
        /**
         * `scripts` in the cache the launcher uses too: `$RTCOORD_CACHE`, else `$XDG_CACHE_HOME/rtcoord`, else
         * `~/.cache/rtcoord`.
         */
        public fun defaultCacheDirectory(): Path {
            val cache =
                System.getenv("RTCOORD_CACHE")?.takeIf { it.isNotEmpty() }?.let { Paths.get(it) }
                    ?: Paths.get(
                        System.getenv("XDG_CACHE_HOME") ?: "${System.getProperty("user.home")}/.cache",
                        "rtcoord",
                    )
            return cache.resolve("scripts")
        }
    }
}

/** A script that does not compile or fails while it runs; [problems] are `file:line:col: message` lines. */
public class ScriptFailure(public val problems: List<String>) : Exception(problems.joinToString("\n"))
