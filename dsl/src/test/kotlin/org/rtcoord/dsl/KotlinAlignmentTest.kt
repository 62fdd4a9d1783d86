package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import javax.xml.parsers.DocumentBuilderFactory
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.w3c.dom.Element

/**
 * A project that depends on rtcoord-dsl gets its Kotlin libraries at one version, the dsl's. Our own build aligns them
 * through the parent's `dependencyManagement`, but a consumer's build does not read it: there, the nearest declaration
 * wins. So every Kotlin library that the dsl's Kotlin dependencies' POMs ask for at another version
 * (kotlin-compiler-embeddable asks for kotlin-reflect 1.6.10) must be a direct dependency of the dsl, which is nearer.
 * The POMs are read from the local repository the build resolved them into.
 */
class KotlinAlignmentTest {
    private val kotlinVersion = System.getProperty("rtcoord.kotlinVersion") ?: error("rtcoord.kotlinVersion not set")
    private val repository =
        Paths.get(System.getProperty("rtcoord.localRepository") ?: error("rtcoord.localRepository not set"))

    @Test
    fun everyKotlinLibraryAskedForAtAnotherVersionIsADirectDependency() {
        val root = Paths.get(System.getProperty("rtcoord.root", ".."))
        val direct = dependencies(root.resolve("dsl/pom.xml")).filter { it.group == KOTLIN }.map { it.artifact }.toSet()
        val misaligned = sortedSetOf<String>()
        val seen = mutableSetOf<String>()
        val pending = ArrayDeque(direct)
        while (pending.isNotEmpty()) {
            val artifact = pending.removeFirst()
            if (!seen.add(artifact)) continue
            val pom = repository.resolve("org/jetbrains/kotlin/$artifact/$kotlinVersion/$artifact-$kotlinVersion.pom")
            if (!Files.exists(pom)) continue
            for (dependency in dependencies(pom)) {
                if (
                    dependency.group != KOTLIN ||
                        dependency.scope !in setOf("compile", "runtime") ||
                        dependency.optional
                )
                    continue
                if (dependency.version == kotlinVersion) pending += dependency.artifact
                else if (dependency.artifact !in direct)
                    misaligned += "${dependency.artifact} ${dependency.version} (asked for by $artifact)"
            }
        }
        assertTrue(seen.size > 1, "no POM of the dsl's Kotlin dependencies found in $repository")
        assertTrue(
            misaligned.isEmpty(),
            "a consumer of rtcoord-dsl would get, beside Kotlin $kotlinVersion: $misaligned",
        )
    }

    private class Dependency(
        val group: String,
        val artifact: String,
        val version: String?,
        val scope: String,
        val optional: Boolean,
    )

    private fun dependencies(pom: Path): List<Dependency> {
        val document = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(pom.toFile())
        val project = document.documentElement
        val declared = project.childElements("dependencies").flatMap { it.childElements("dependency") }
        return declared.map { element ->
            fun text(name: String) = element.childElements(name).firstOrNull()?.textContent?.trim()
            Dependency(
                text("groupId").orEmpty(),
                text("artifactId").orEmpty(),
                text("version"),
                text("scope") ?: "compile",
                text("optional") == "true",
            )
        }
    }

    private fun Element.childElements(name: String): List<Element> =
        (0 until childNodes.length)
            .map { childNodes.item(it) }
            .filterIsInstance<Element>()
            .filter { it.tagName == name }

    private companion object {
        const val KOTLIN = "org.jetbrains.kotlin"
    }
}
