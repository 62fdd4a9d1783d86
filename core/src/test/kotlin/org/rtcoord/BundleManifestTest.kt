package org.rtcoord

import java.io.File
import java.util.jar.JarFile
import java.util.jar.Manifest
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** The core and idl jars are OSGi bundles exporting only their public packages. */
class BundleManifestTest {
    /** The manifest of the jar or class directory [type] was loaded from. */
    private fun manifestOf(type: Class<*>): Manifest {
        val location = File(type.protectionDomain.codeSource.location.toURI())
        return if (location.isFile) JarFile(location).use { it.manifest }
        else File(location, "META-INF/MANIFEST.MF").inputStream().use(::Manifest)
    }

    /** Package names in Export-Package, whose clauses are split by commas outside quoted values. */
    private fun exported(manifest: Manifest): Set<String> {
        val clauses = mutableListOf(StringBuilder())
        var quoted = false
        for (char in manifest.mainAttributes.getValue("Export-Package").orEmpty()) {
            when {
                char == '"' -> {
                    quoted = !quoted
                    clauses.last().append(char)
                }
                char == ',' && !quoted -> clauses += StringBuilder()
                else -> clauses.last().append(char)
            }
        }
        return clauses.map { it.toString().substringBefore(';').trim() }.filter { it.isNotEmpty() }.toSet()
    }

    @Test
    fun `core exports its API package and keeps the implementation private`() {
        val manifest = manifestOf(RtcTree::class.java)
        assertEquals("org.rtcoord.core", manifest.mainAttributes.getValue("Bundle-SymbolicName"))
        assertEquals(setOf("org.rtcoord", "org.rtcoord.java", "org.rtcoord.profile"), exported(manifest))
        val imports = manifest.mainAttributes.getValue("Import-Package")
        assertTrue(imports.contains("RTC") && imports.contains("kotlinx.coroutines"), imports)
    }

    @Test
    fun `idl exports the generated interface packages`() {
        val manifest = manifestOf(RTC.RTObject::class.java)
        assertEquals("org.rtcoord.idl", manifest.mainAttributes.getValue("Bundle-SymbolicName"))
        assertEquals(setOf("RTC", "_SDOPackage", "OpenRTM", "RTM", "org.rtcoord.idl"), exported(manifest))
    }
}
