@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import kotlin.script.experimental.api.ResultValue
import kotlin.script.experimental.api.ResultWithDiagnostics
import kotlin.script.experimental.api.ScriptEvaluationConfiguration
import kotlin.script.experimental.api.constructorArgs
import kotlin.script.experimental.host.toScriptSource
import kotlin.script.experimental.jvm.BasicJvmScriptEvaluator
import kotlin.script.experimental.jvm.baseClassLoader
import kotlin.script.experimental.jvm.jvm
import kotlin.script.experimental.jvmhost.JvmScriptCompiler
import kotlin.script.experimental.jvmhost.createJvmCompilationConfigurationFromTemplate
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.dsl.script.CompiledScripts
import org.rtcoord.dsl.script.CoordinatorScript
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.dsl.script.ScriptProblems

/**
 * Compiles (or takes from [cacheDirectory], as coordinators are) and evaluates `*.test.kts` files into the
 * [CoordinatorTest] they declare.
 */
internal class TestScriptHost(cacheDirectory: Path? = ScriptHost.defaultCacheDirectory()) {
    private val compilation = createJvmCompilationConfigurationFromTemplate<TestScript>()
    private val compiler =
        JvmScriptCompiler(CompiledScripts.host(cacheDirectory, TestScript::class.java, CoordinatorScript::class.java))
    private val evaluator = BasicJvmScriptEvaluator()

    /**
     * The test [file] declares; throws [ScriptFailure] with `file:line:col: message` lines when it does not compile or
     * run.
     */
    suspend fun load(file: Path): CoordinatorTest {
        if (!Files.isRegularFile(file)) throw ScriptFailure(listOf("$file:1:1: no such file"))
        val compiled =
            when (val result = compiler(file.toFile().toScriptSource(), compilation)) {
                is ResultWithDiagnostics.Success -> result.value
                is ResultWithDiagnostics.Failure -> throw ScriptFailure(ScriptProblems.of(file, result.reports))
            }
        val evaluation = ScriptEvaluationConfiguration {
            constructorArgs(file.toAbsolutePath().parent, file.fileName.toString())
            jvm { baseClassLoader(TestScriptHost::class.java.classLoader) }
        }
        return when (val result = evaluator(compiled, evaluation)) {
            is ResultWithDiagnostics.Failure -> throw ScriptFailure(ScriptProblems.of(file, result.reports))
            is ResultWithDiagnostics.Success ->
                when (val value = result.value.returnValue) {
                    is ResultValue.Error ->
                        throw ScriptFailure(listOf(ScriptProblems.thrown(file.toString(), value.error)))
                    else ->
                        value.scriptInstance as? CoordinatorTest
                            ?: throw ScriptFailure(listOf("$file:1:1: the script did not produce a test"))
                }
        }
    }
}
