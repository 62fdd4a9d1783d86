package org.rtcoord.dsl.script

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.security.MessageDigest
import kotlin.script.experimental.api.SourceCode
import kotlin.script.experimental.host.ScriptingHostConfiguration
import kotlin.script.experimental.jvm.compilationCache
import kotlin.script.experimental.jvm.defaultJvmScriptingHostConfiguration
import kotlin.script.experimental.jvm.jvm
import kotlin.script.experimental.jvmhost.CompiledScriptJarsCache
import org.rtcoord.InternalRtcoordApi

/**
 * Scripts compiled once and kept as jars, so that an unchanged script starts without compiling: the coordinators
 * [ScriptHost] runs and the `*.test.kts` tests of `rtcoord test` alike.
 */
@InternalRtcoordApi
public object CompiledScripts {
    /**
     * A scripting host that keeps what it compiles in [directory] (nothing when null), by a hash of the script's text,
     * of the compiler, and of the jars [templates] were loaded from: a rebuilt DSL or template invalidates the scripts
     * compiled against the old one.
     */
    public fun host(directory: Path?, vararg templates: Class<*>): ScriptingHostConfiguration =
        ScriptingHostConfiguration(defaultJvmScriptingHostConfiguration) {
            directory?.let {
                jvm { compilationCache(CompiledScriptJarsCache { source, _ -> jarOf(it, source, templates) }) }
            }
        }

    private fun jarOf(directory: Path, source: SourceCode, templates: Array<out Class<*>>): File {
        val digest = MessageDigest.getInstance("SHA-256")
        digest.update(source.text.toByteArray())
        digest.update(KotlinVersion.CURRENT.toString().toByteArray())
        for (template in templates) {
            val jar = File(template.protectionDomain.codeSource.location.toURI())
            digest.update("${jar.lastModified()}:${jar.length()}".toByteArray())
        }
        Files.createDirectories(directory)
        return directory.resolve(digest.digest().joinToString("") { "%02x".format(it) } + ".jar").toFile()
    }
}
