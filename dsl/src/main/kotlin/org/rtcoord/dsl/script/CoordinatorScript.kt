@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.script

import java.nio.file.Path
import kotlin.script.experimental.annotations.KotlinScript
import kotlin.script.experimental.api.ScriptAcceptedLocation
import kotlin.script.experimental.api.ScriptCompilationConfiguration
import kotlin.script.experimental.api.acceptedLocations
import kotlin.script.experimental.api.compilerOptions
import kotlin.script.experimental.api.defaultImports
import kotlin.script.experimental.api.ide
import kotlin.script.experimental.jvm.jvm
import kotlin.script.experimental.jvm.updateClasspath
import kotlin.script.experimental.jvm.util.scriptCompilationClasspathFromContext
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination

/**
 * The script definition of `*.coord.kts` coordinators: the script body is a [Coordination], with the core API, the DSL,
 * lifecycle states (`ERROR`, `ACTIVE`, ...), duration units and `delay` imported; [directory] is the script's own, and
 * [name] its file name.
 */
@KotlinScript(
    displayName = "rtcoord coordinator",
    fileExtension = "coord.kts",
    compilationConfiguration = CoordinatorScriptCompilation::class,
)
public abstract class CoordinatorScript(args: Array<String>, host: TreeConfig, directory: Path, name: String) :
    Coordination(args.toList(), host, directory, name)

/** How coordinator scripts compile: default imports, and the host's class path as the script's. */
public object CoordinatorScriptCompilation :
    ScriptCompilationConfiguration({
        defaultImports(
            "org.rtcoord.*",
            "org.rtcoord.dsl.*",
            "org.rtcoord.LifeCycle.*",
            "kotlin.time.Duration.Companion.milliseconds",
            "kotlin.time.Duration.Companion.seconds",
            "kotlin.time.Duration.Companion.minutes",
            "kotlinx.coroutines.delay",
            *LogLevelNames.imports.toTypedArray(),
        )
        jvm {
            // The host's class path less the compiler's own jars, which no script names: a cached script's jar lists
            // its class path, and the JVM that loads it would open them (`rtcoord run` runs without the compiler).
            updateClasspath(
                scriptCompilationClasspathFromContext(wholeClasspath = true).filterNot { jar ->
                    COMPILER_JARS.any { jar.name.startsWith("$it-") }
                }
            )
        }
        // The DSL's inline words (`data<TimedDoubleSeq> { }`) are JVM 17 bytecode, which a script can inline only at
        // the same target.
        compilerOptions("-jvm-target", "17")
        ide {
            acceptedLocations(ScriptAcceptedLocation.Everywhere)
        }
    }) {
    private fun readResolve(): Any = CoordinatorScriptCompilation
}

/** The Kotlin compiler's jars, by artifact: the compiling JVM's, never a script's. */
private val COMPILER_JARS =
    listOf(
        "kotlin-compiler-embeddable",
        "kotlin-daemon-embeddable",
        "kotlin-scripting-compiler-embeddable",
        "kotlin-scripting-compiler-impl-embeddable",
    )
