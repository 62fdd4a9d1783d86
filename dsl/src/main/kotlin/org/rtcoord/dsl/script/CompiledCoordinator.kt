@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.script

import java.io.IOException
import java.lang.reflect.Constructor
import java.lang.reflect.InvocationTargetException
import java.nio.file.Files
import java.nio.file.Path
import java.util.Properties
import java.util.jar.Attributes
import java.util.jar.JarInputStream
import java.util.jar.Manifest
import java.util.zip.ZipException
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination

/**
 * A coordinator compiled ahead of time (`rtcoord compile SCRIPT.coord.kts -o NAME.jar`, or [ScriptHost.compile]): a jar
 * of the script's classes, its text, and a manifest naming the script class and the rtcoord version that compiled it.
 * Loading it needs no Kotlin compiler and no scripting host, only the dsl and what it runs on (Kotlin's standard
 * library, kotlinx-coroutines, core): what an Eclipse plug-in has in rtcoord's OSGi bundle. The classes are read into
 * memory, so the jar is not held open.
 *
 * A jar compiled by another rtcoord version is refused, naming both versions: the script's classes are compiled against
 * the DSL they were built with, and call it by its binary names.
 */
public object CompiledCoordinator {
    /** The manifest attribute naming the script class. */
    internal const val SCRIPT_CLASS = "Rtcoord-Coordinator"

    /** The manifest attribute naming the rtcoord version that compiled the jar. */
    internal const val COMPILED_BY = "Rtcoord-Version"

    /** The manifest attribute naming the script's file (`restart.coord.kts`): the coordinator's name. */
    internal const val SCRIPT_NAME = "Rtcoord-Script"

    /** Where the jar keeps the script's text, for `check` and for the lines of failures. */
    internal const val SOURCE_ENTRY = "META-INF/rtcoord/script.coord.kts"

    /** This rtcoord's version: the one a compiled coordinator must have been compiled by. */
    @JvmStatic
    public val version: String by lazy {
        CompiledCoordinator::class.java.getResourceAsStream("version.properties")?.use {
            Properties().apply { load(it) }.getProperty("version")
        } ?: "unknown"
    }

    /** Whether [file] is taken for a compiled coordinator rather than a script: its name ends in `.jar`. */
    @JvmStatic public fun isCompiled(file: Path): Boolean = file.fileName.toString().endsWith(".jar", ignoreCase = true)

    /**
     * Evaluates the coordinator compiled into [jar] with [args], its host running it on [host], and returns what it
     * declared; the script's relative file names are relative to the jar's directory.
     *
     * @throws ScriptFailure when [jar] cannot be read, is not a compiled coordinator (naming its path), was compiled by
     *   another rtcoord version (naming both), or the script's body throws (naming its line).
     */
    @JvmStatic
    @JvmOverloads
    @Throws(ScriptFailure::class)
    public fun load(jar: Path, args: List<String> = emptyList(), host: TreeConfig = TreeConfig()): Coordination {
        val contents = read(jar)
        val manifest = contents.manifest?.mainAttributes
        val className =
            manifest?.getValue(SCRIPT_CLASS)
                ?: refuse(
                    jar,
                    "not a compiled coordinator: its manifest has no $SCRIPT_CLASS (compile one with rtcoord compile)",
                )
        val compiledBy = manifest.getValue(COMPILED_BY) ?: "an unknown version"
        if (compiledBy != version)
            refuse(jar, "compiled by rtcoord $compiledBy, and this is rtcoord $version: compile it again with this one")
        val name = manifest.getValue(SCRIPT_NAME) ?: jar.fileName.toString()
        val constructor = scriptConstructor(contents, className) { refuse(jar, it) }
        return instantiate(constructor, args, host, jar.toAbsolutePath().parent, name, name)
    }

    /**
     * Evaluates [script] from [kept], the jar its scripting host kept it in once compiled (the script class named by
     * the jar's `Main-Class`), as [load] evaluates a compiled coordinator. Neither the scripting host nor Kotlin's full
     * reflection is started: the host reads a template's annotations with it, and its 800 classes stay loaded for as
     * long as the coordinator runs (13 MB of `rtcoord run`'s 81). Returns null when [kept] does not hold a coordinator
     * script that links against this rtcoord: it is compiled again.
     *
     * @throws ScriptFailure when the script's body throws (naming its line).
     */
    internal fun loadKept(kept: Path, script: Path, args: List<String>, host: TreeConfig): Coordination? {
        val contents =
            try {
                read(kept)
            } catch (e: ScriptFailure) {
                return null
            }
        val className = contents.manifest?.mainAttributes?.getValue(Attributes.Name.MAIN_CLASS) ?: return null
        val constructor =
            scriptConstructor(contents, className) {
                return null
            }
        val directory = script.toAbsolutePath().parent
        return instantiate(constructor, args, host, directory, script.fileName.toString(), script.toString())
    }

    /**
     * The constructor of the coordinator script class [className] of [contents], which a coordinator script is made
     * with; [refuse] says why there is none.
     */
    private inline fun scriptConstructor(
        contents: Contents,
        className: String,
        refuse: (String) -> Nothing,
    ): Constructor<*> {
        val type =
            try {
                Class.forName(
                    className,
                    true,
                    ScriptClasses(contents.entries, CoordinatorScript::class.java.classLoader),
                )
            } catch (e: ClassNotFoundException) {
                refuse("not a compiled coordinator: it has no class $className, which its manifest names")
            } catch (e: LinkageError) {
                refuse("its classes do not link against this rtcoord: ${e.message}")
            }
        if (!CoordinatorScript::class.java.isAssignableFrom(type))
            refuse("not a compiled coordinator: $className is not a coordinator script")
        return try {
            type.getConstructor(Array<String>::class.java, TreeConfig::class.java, Path::class.java, String::class.java)
        } catch (e: NoSuchMethodException) {
            refuse("not a compiled coordinator: $className has no coordinator script's constructor")
        }
    }

    /**
     * Makes the script with [constructor]: its body runs. A body that throws is a [ScriptFailure] naming [location] and
     * the line.
     */
    private fun instantiate(
        constructor: Constructor<*>,
        args: List<String>,
        host: TreeConfig,
        directory: Path,
        name: String,
        location: String,
    ): Coordination =
        try {
            constructor.newInstance(args.toTypedArray(), host, directory, name) as Coordination
        } catch (e: InvocationTargetException) {
            throw ScriptFailure(listOf(ScriptProblems.thrown(location, e.cause ?: e)))
        }

    /** The text of the script compiled into [jar]. @throws ScriptFailure when it cannot be read or holds none. */
    @JvmStatic
    @Throws(ScriptFailure::class)
    public fun source(jar: Path): String =
        read(jar).entries[SOURCE_ENTRY]?.toString(Charsets.UTF_8)
            ?: refuse(jar, "not a compiled coordinator: it holds no script text")

    private class Contents(val manifest: Manifest?, val entries: Map<String, ByteArray>)

    private fun read(jar: Path): Contents =
        try {
            JarInputStream(Files.newInputStream(jar)).use { input ->
                val entries = HashMap<String, ByteArray>()
                generateSequence { input.nextJarEntry }
                    .filterNot { it.isDirectory }
                    .forEach { entries[it.name] = input.readBytes() }
                if (input.manifest == null && entries.isEmpty()) refuse(jar, "not a compiled coordinator: not a jar")
                Contents(input.manifest, entries)
            }
        } catch (e: ZipException) {
            refuse(jar, "not a compiled coordinator: not a jar (${e.message})")
        } catch (e: IOException) {
            refuse(jar, "cannot read it: ${e.message ?: e.javaClass.simpleName}")
        }

    private fun refuse(jar: Path, why: String): Nothing = throw ScriptFailure(listOf("$jar: $why"))
}

/** The classes of a compiled coordinator, defined from the bytes read out of its jar. */
private class ScriptClasses(private val entries: Map<String, ByteArray>, parent: ClassLoader?) : ClassLoader(parent) {
    override fun findClass(name: String): Class<*> {
        val bytes = entries[name.replace('.', '/') + ".class"] ?: throw ClassNotFoundException(name)
        return defineClass(name, bytes, 0, bytes.size)
    }
}
