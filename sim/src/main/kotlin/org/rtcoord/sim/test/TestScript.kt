@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import java.nio.file.Path
import kotlin.script.experimental.annotations.KotlinScript
import kotlin.script.experimental.api.ScriptAcceptedLocation
import kotlin.script.experimental.api.ScriptCompilationConfiguration
import kotlin.script.experimental.api.acceptedLocations
import kotlin.script.experimental.api.compilerOptions
import kotlin.script.experimental.api.defaultImports
import kotlin.script.experimental.api.ide
import kotlin.script.experimental.jvm.dependenciesFromCurrentContext
import kotlin.script.experimental.jvm.jvm
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.dsl.script.LogLevelNames

/**
 * The script definition of `*.test.kts` coordinator tests: the body is a [CoordinatorTest], with the core API,
 * lifecycle states (`ACTIVE`, `ERROR`, ...) and duration units imported, as in coordinators.
 */
@KotlinScript(
    displayName = "rtcoord coordinator test",
    fileExtension = "test.kts",
    compilationConfiguration = TestScriptCompilation::class,
)
public abstract class TestScript(directory: Path, name: String) : CoordinatorTest(directory, name)

/** How test scripts compile: the imports coordinators have, and the host's class path. */
public object TestScriptCompilation :
    ScriptCompilationConfiguration({
        defaultImports(
            "org.rtcoord.*",
            "org.rtcoord.LifeCycle.*",
            "org.rtcoord.sim.test.*",
            "kotlin.time.Duration.Companion.milliseconds",
            "kotlin.time.Duration.Companion.seconds",
            "kotlin.time.Duration.Companion.minutes",
            *LogLevelNames.imports.toTypedArray(),
        )
        jvm {
            dependenciesFromCurrentContext(wholeClasspath = true)
        }
        compilerOptions("-jvm-target", "17")
        ide {
            acceptedLocations(ScriptAcceptedLocation.Everywhere)
        }
    }) {
    private fun readResolve(): Any = TestScriptCompilation
}
