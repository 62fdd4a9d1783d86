package org.rtcoord.profile

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.BadParameterException
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * OpenRTM-aist's ConfigSample holds values outside its own `__constraints__` (OpenRTM-aist never checks them): a
 * profile saved from it restores onto it unchanged, a value written outside a constraint is a warning, and strict
 * callers have it refused.
 */
class ConstraintRoundTripTest {
    private val naming = NamingService.start()
    private val system = Scenarios.configSample(naming.corbaloc)
    private val tree = RtcTree(TreeConfig(nameServers = listOf(naming.address)))
    private val profiles = SystemProfiles(tree)
    private val path = "/${naming.address}/${RuntimeProcess.hostContext}/ConfigSample0.rtc"
    private val outside = "$path: configuration set 'mode0': int_param0: '12345' is outside 0<=x<=150"

    @AfterEach
    fun close() {
        tree.close()
        system.close()
        naming.close()
    }

    @Test
    fun `a profile saved from the system restores onto it unchanged, strict or not`() = runBlocking {
        val saved = profiles.save()
        assertEquals("12345", saved.components.single().configurationSet("mode0")!!.data["int_param0"])
        for (strict in listOf(false, true)) {
            val report = profiles.restore(saved, strict = strict)
            assertEquals(emptyList<String>(), report.done + report.warnings, "strict = $strict")
        }
        assertEquals(emptyList<ProfileDifference>(), profiles.check(saved, state = null))
    }

    @Test
    fun `restoring a value outside its constraint writes it with a warning, and strict refuses it changing nothing`() =
        runBlocking {
            val saved = profiles.save()
            val sample = tree.component(path)
            sample.setParameters(mapOf("int_param0" to "100", "str_param1" to "changed"), "mode0")

            val refused =
                assertThrows<ProfileRefusedException> { runBlocking { profiles.restore(saved, strict = true) } }
            assertEquals(outside, refused.reason)
            assertEquals(
                "100",
                sample.configuration().sets.getValue("mode0")["int_param0"],
                "the strict restore wrote nothing",
            )
            assertEquals(
                "changed",
                sample.configuration().sets.getValue("mode0")["str_param1"],
                "the strict restore wrote nothing",
            )

            val report = profiles.restore(saved)
            assertEquals(listOf(outside), report.warnings)
            assertEquals(listOf("$path: set int_param0, str_param1 in 'mode0'"), report.done)
            assertEquals(emptyList<ProfileDifference>(), profiles.check(saved, state = null))
        }

    @Test
    fun `setting a value outside its constraint warns, strict refuses it, and a value held already passes either way`() =
        runBlocking {
            val sample = tree.component(path)
            assertEquals(
                listOf("int_param0: '200' is outside 0<=x<=150"),
                sample.setParameter("int_param0", "200", "mode1"),
            )
            assertEquals("200", sample.configuration().sets.getValue("mode1")["int_param0"])
            val refused =
                assertThrows<BadParameterException> {
                    runBlocking { sample.setParameter("int_param0", "300", "mode1", strict = true) }
                }
            assertEquals("$path: set int_param0 rejected: '300' is outside 0<=x<=150", refused.message)
            assertEquals("200", sample.configuration().sets.getValue("mode1")["int_param0"])
            assertEquals(
                emptyList<String>(),
                sample.setParameters(mapOf("int_param0" to "12345", "int_param1" to "5"), "mode0", strict = true),
            )
        }
}
