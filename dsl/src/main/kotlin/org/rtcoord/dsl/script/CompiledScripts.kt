package org.rtcoord.dsl.script

import java.io.File
import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption.ATOMIC_MOVE
import java.nio.file.StandardCopyOption.REPLACE_EXISTING
import java.security.MessageDigest
import java.util.zip.ZipFile
import kotlin.script.experimental.api.CompiledScript
import kotlin.script.experimental.api.ScriptCompilationConfiguration
import kotlin.script.experimental.api.SourceCode
import kotlin.script.experimental.host.ScriptingHostConfiguration
import kotlin.script.experimental.jvm.CompiledJvmScriptsCache
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
                jvm { compilationCache(WholeJars { source -> jarOf(it, source, templates) }) }
            }
        }

    /**
     * The jar [directory] keeps [source] in, compiled against [templates]; null when it keeps none. A jar cut short (by
     * a process killed while writing it) is deleted, to be compiled again. Loading it needs neither the compiler nor
     * the scripting host ([CompiledCoordinator.loadKept]).
     */
    internal fun kept(directory: Path, source: SourceCode, vararg templates: Class<*>): Path? =
        keptJar(jarOf(directory, source, templates))?.toPath()

    /** [jar] if it is there and whole; a jar cut short is deleted. */
    private fun keptJar(jar: File): File? {
        if (!jar.isFile) return null
        // Read lazily, a jar cut short would fail only once the script runs: its central directory, at its end, tells
        // it now.
        val whole =
            try {
                ZipFile(jar).close()
                true
            } catch (e: IOException) {
                false
            }
        if (!whole) jar.delete()
        return jar.takeIf { whole }
    }

    private fun jarOf(directory: Path, source: SourceCode, templates: Array<out Class<*>>): File {
        val digest = MessageDigest.getInstance("SHA-256")
        digest.update(source.text.toByteArray())
        digest.update(KotlinVersion.CURRENT.toString().toByteArray())
        for (template in templates) {
            val jar = File(template.protectionDomain.codeSource.location.toURI())
            digest.update("${jar.lastModified()}:${jar.length()}".toByteArray())
        }
        return directory.resolve(digest.digest().joinToString("") { "%02x".format(it) } + ".jar").toFile()
    }

    /**
     * Jars written whole or not at all: each is written beside its place and moved there in one step, so another
     * process compiling the same script at the same time (two `rtcoord run`s, test JVMs side by side) never reads half
     * of one. A jar that cannot be read (cut short by a process killed while writing it) is compiled again, not an
     * error at every start.
     */
    private class WholeJars(private val jarOf: (SourceCode) -> File) : CompiledJvmScriptsCache {
        override fun get(
            script: SourceCode,
            scriptCompilationConfiguration: ScriptCompilationConfiguration,
        ): CompiledScript? {
            val jar = keptJar(jarOf(script)) ?: return null
            return CompiledScriptJarsCache { _, _ -> jar }.get(script, scriptCompilationConfiguration)
        }

        override fun store(
            compiledScript: CompiledScript,
            script: SourceCode,
            scriptCompilationConfiguration: ScriptCompilationConfiguration,
        ) {
            val jar = jarOf(script).toPath()
            Files.createDirectories(jar.parent)
            val part = Files.createTempFile(jar.parent, jar.fileName.toString(), ".part")
            try {
                CompiledScriptJarsCache { _, _ -> part.toFile() }
                    .store(compiledScript, script, scriptCompilationConfiguration)
                Files.move(part, jar, ATOMIC_MOVE, REPLACE_EXISTING)
            } finally {
                Files.deleteIfExists(part)
            }
        }
    }
}
