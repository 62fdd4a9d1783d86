package org.rtcoord.idl

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.streams.asSequence
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** The jar holds client stubs and servant skeletons for every interface a coordinator or fixture uses. */
class GeneratedBindingsTest {
    private val interfaces =
        mapOf(
            "RTC.LightweightRTObject" to "IDL:omg.org/RTC/LightweightRTObject:1.0",
            "RTC.RTObject" to "IDL:omg.org/RTC/RTObject:1.0",
            "RTC.DataFlowComponent" to "IDL:omg.org/RTC/DataFlowComponent:1.0",
            "RTC.ExecutionContextService" to "IDL:omg.org/RTC/ExecutionContextService:1.0",
            "RTC.PortService" to "IDL:omg.org/RTC/PortService:1.0",
            "RTC.ComponentObserver" to "IDL:omg.org/RTC/ComponentObserver:1.0",
            "RTC.FsmService" to "IDL:omg.org/RTC/FsmService:1.0",
            "RTC.ExtendedFsmService" to "IDL:omg.org/RTC/ExtendedFsmService:1.0",
            "RTC.MultiModeObject" to "IDL:omg.org/RTC/MultiModeObject:1.0",
            "_SDOPackage.SDO" to "IDL:org.omg/SDOPackage/SDO:1.0",
            "_SDOPackage.Configuration" to "IDL:org.omg/SDOPackage/Configuration:1.0",
            "_SDOPackage.SDOService" to "IDL:org.omg/SDOPackage/SDOService:1.0",
            "OpenRTM.DataFlowComponent" to "IDL:openrtm.aist.go.jp/OpenRTM/DataFlowComponent:1.0",
            "OpenRTM.ExtTrigExecutionContextService" to
                "IDL:openrtm.aist.go.jp/OpenRTM/ExtTrigExecutionContextService:1.0",
            "OpenRTM.ComponentObserver" to "IDL:OpenRTM/ComponentObserver:1.0",
            "OpenRTM.InPortCdr" to "IDL:OpenRTM/InPortCdr:1.0",
            "OpenRTM.OutPortCdr" to "IDL:OpenRTM/OutPortCdr:1.0",
            "RTM.Manager" to "IDL:RTM/Manager:1.0",
        )

    @Test
    fun `every interface has a stub, a POA skeleton, a tie and a helper with its repository id`() {
        for ((name, id) in interfaces) {
            val dot = name.lastIndexOf('.')
            val stub = name.substring(0, dot + 1) + "_" + name.substring(dot + 1) + "Stub"
            listOf(name, stub, "${name}POA", "${name}POATie", "${name}Operations").forEach { Class.forName(it) }
            assertEquals(id, helperId(name), name)
        }
    }

    @Test
    fun `data types keep their unprefixed repository ids`() {
        assertEquals("IDL:RTC/TimedLong:1.0", helperId("RTC.TimedLong"))
        assertEquals("IDL:RTC/TimedDoubleSeq:1.0", helperId("RTC.TimedDoubleSeq"))
        assertEquals("IDL:OpenRTM/PortStatus:1.0", helperId("OpenRTM.PortStatus"))
        assertEquals("IDL:omg.org/RTC/ReturnCode_t:1.0", helperId("RTC.ReturnCode_t"))
        assertEquals("IDL:org.omg/SDOPackage/InvalidParameter:1.0", helperId("_SDOPackage.InvalidParameter"))
    }

    @Test
    fun `no compiled class refers to the Java package name as a repository id`() {
        val classes = Paths.get(RTC.RTObject::class.java.protectionDomain.codeSource.location.toURI())
        val offenders =
            Files.walk(classes).use { paths ->
                paths
                    .asSequence()
                    .filter { it.toString().endsWith(".class") }
                    .filter { String(Files.readAllBytes(it), Charsets.ISO_8859_1).contains("IDL:org.omg/_SDOPackage/") }
                    .map(Path::toString)
                    .toList()
            }
        assertTrue(offenders.isEmpty(), "classes carrying IDL:org.omg/_SDOPackage/: $offenders")
    }

    private fun helperId(type: String): String = Class.forName("${type}Helper").getMethod("id").invoke(null) as String
}
