package org.rtcoord.cli

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import kotlin.io.path.extension

/**
 * The Kotlin compiler's jars, which the CLI jar's Class-Path leaves out (cli/pom.xml): a resource or service that no
 * jar on the class path has (JacORB's configuration files, a `ServiceLoader`) opens every jar there, and the compiler's
 * index then stays in the heap for as long as the JVM runs, 3.3 MB of it. `watch` was 5.4 MB smaller without them. They
 * are kept in `lib/compiler` beside the jar's libraries: the launcher (bin/rtcoord) adds them for the commands that
 * compile (check, compile, demo, test), and `run` compiles its script in a JVM that has them ([CompilerProcess]).
 */
internal object CompilerJars {
    /** Whether this JVM can compile scripts: the compiler is on its class path (the launcher's, or a test's). */
    val present: Boolean by lazy {
        CompilerJars::class.java.classLoader.getResource("org/jetbrains/kotlin/config/CompilerConfiguration.class") !=
            null
    }

    /**
     * The compiler's jars as a class path, found beside the CLI's jar: `target/lib/compiler` next to the built jar, or
     * `lib/compiler` holding the distribution's `lib/rtcoord-cli.jar`. Empty where there are none.
     */
    val classPath: String by lazy {
        val jar = Path.of(CompilerJars::class.java.protectionDomain.codeSource.location.toURI())
        val directory =
            listOf(jar.resolveSibling("lib").resolve("compiler"), jar.resolveSibling("compiler")).firstOrNull {
                Files.isDirectory(it)
            }
        directory
            ?.let { dir -> Files.list(dir).use { jars -> jars.filter { it.extension == "jar" }.sorted().toList() } }
            .orEmpty()
            .joinToString(File.pathSeparator)
    }

    /** Fails [command] with one line saying how to run it, when this JVM cannot compile. */
    fun require(command: String) {
        if (!present)
            throw CommandFailed(
                "$command needs the Kotlin compiler, which bin/rtcoord adds to the class path: run it with bin/rtcoord " +
                    "(or java -cp with lib/compiler/*.jar added)"
            )
    }
}
