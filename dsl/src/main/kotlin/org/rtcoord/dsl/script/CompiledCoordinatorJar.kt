package org.rtcoord.dsl.script

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption
import java.util.jar.Attributes
import java.util.jar.JarEntry
import java.util.jar.JarOutputStream
import java.util.jar.Manifest
import kotlin.script.experimental.api.CompiledScript
import kotlin.script.experimental.jvm.impl.KJvmCompiledModuleInMemory
import kotlin.script.experimental.jvm.impl.KJvmCompiledScript

/**
 * Writes what the compiler made of a script as the jar [CompiledCoordinator] loads: its classes, its text and a
 * manifest naming the script class, the script and this rtcoord's version. Kept apart from the loader, which must not
 * reach the scripting host's classes.
 */
internal object CompiledCoordinatorJar {
    fun write(compiled: CompiledScript, text: String, scriptName: String, jar: Path) {
        val script =
            compiled as? KJvmCompiledScript
                ?: throw ScriptFailure(
                    listOf("$scriptName: the compiler gave no classes to write (${compiled.javaClass.name})")
                )
        val module =
            script.getCompiledModule() as? KJvmCompiledModuleInMemory
                ?: throw ScriptFailure(
                    listOf(
                        "$scriptName: the compiler gave no classes to write (${script.getCompiledModule()?.javaClass?.name})"
                    )
                )
        val manifest =
            Manifest().apply {
                mainAttributes[Attributes.Name.MANIFEST_VERSION] = "1.0"
                mainAttributes[Attributes.Name(CompiledCoordinator.SCRIPT_CLASS)] = script.scriptClassFQName
                mainAttributes[Attributes.Name(CompiledCoordinator.COMPILED_BY)] = CompiledCoordinator.version
                mainAttributes[Attributes.Name(CompiledCoordinator.SCRIPT_NAME)] = scriptName
                mainAttributes[Attributes.Name("Created-By")] = "rtcoord ${CompiledCoordinator.version}"
            }
        val target = jar.toAbsolutePath()
        try {
            Files.createDirectories(target.parent)
            // Written beside, then moved: a coordinator that is running from the old jar's path never reads half a jar.
            val partial = Files.createTempFile(target.parent, ".${target.fileName}", ".partial")
            try {
                JarOutputStream(Files.newOutputStream(partial), manifest).use { out ->
                    fun add(name: String, bytes: ByteArray) {
                        out.putNextEntry(JarEntry(name))
                        out.write(bytes)
                        out.closeEntry()
                    }
                    add(CompiledCoordinator.SOURCE_ENTRY, text.toByteArray(Charsets.UTF_8))
                    module.compilerOutputFiles.toSortedMap().forEach { (name, bytes) ->
                        if (name != "META-INF/MANIFEST.MF") add(name, bytes)
                    }
                }
                Files.move(partial, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
            } finally {
                Files.deleteIfExists(partial)
            }
        } catch (e: IOException) {
            throw ScriptFailure(listOf("$jar: cannot write it: ${e.message ?: e.javaClass.simpleName}"))
        }
    }
}
