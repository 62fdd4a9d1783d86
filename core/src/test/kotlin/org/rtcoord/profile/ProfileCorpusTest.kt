package org.rtcoord.profile

import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.ValueSource

/** Every profile of the corpus is read, written and read again, in both forms, with nothing lost. */
class ProfileCorpusTest {
    @ParameterizedTest
    @ValueSource(strings = ["full-system.xml", "beyond-rtsprofile.xml", "full-system-by-rtsprofile.yaml"])
    fun `a corpus profile survives a round trip in its own form and in the other`(name: String) {
        val read = RtsProfiles.read(corpus(name))
        val own = RtsProfiles.formatOf(name, "")
        assertEquals(read, RtsProfiles.parse(RtsProfiles.write(read, own), own, "$name again"), "$name written as $own")
        // Content outside the schema is kept exactly within one form; across forms, what the schema names is.
        val other = ProfileFormat.entries.single { it != own }
        assertEquals(
            read.withoutForeign(),
            RtsProfiles.parse(RtsProfiles.write(read, other), other, "$name as $other").withoutForeign(),
            "$name written as $other",
        )
    }

    @Test
    fun `every element of the schema is read`() {
        val profile = RtsProfiles.read(corpus("full-system.xml"))
        assertEquals("RTSystem:AIST:Localisation:1.0", profile.id)
        assertEquals("whole system", profile.ext.comment)
        assertEquals(mapOf("system.owner" to "lab"), profile.ext.properties)
        val laser = profile.components.first { it.instanceName == "laser0" }
        assertEquals("fast", laser.activeConfigurationSet)
        assertEquals(mapOf("range" to "10.0", "mode" to "fast"), laser.configurationSet("fast")!!.data)
        assertEquals(listOf("default", "fast", "empty"), laser.configurationSets.map { it.id })
        assertEquals(Location(120, 80, 80, 60, "LEFT"), laser.ext.location)
        assertEquals(mapOf("IOR" to "IOR:000000", "OpenRTM_NS" to ""), laser.ext.properties)
        assertEquals("control service", laser.servicePorts.single().ext.comment)
        assertEquals(1000.0, laser.executionContexts.single().rate)
        assertEquals(mapOf("sync_transition" to "YES"), laser.executionContexts.single().ext.properties)
        val scan = profile.dataPortConnectors.first { it.connectorId == "conn-laser" }
        assertEquals("periodic", scan.subscriptionType)
        assertEquals(20.0, scan.pushInterval)
        assertEquals("laser", scan.source.shortPortName)
        assertEquals("8", scan.connectionProperties()["dataport.buffer.length"])
        assertEquals("CORBA", profile.servicePortConnectors.single().transMethod)
        val activation = profile.orderings.getValue(OrderingKind.ACTIVATION).targets
        assertEquals(Condition.WaitTime(200), activation.first { it.target.instanceName == "odometry0" }.condition)
        val preceding = activation.first { it.target.instanceName == "localise0" }.condition as Condition.Preceding
        assertEquals(listOf("laser0", "odometry0"), preceding.components.map { it.instanceName })
        assertEquals(3000 to "SYNC", preceding.timeoutMillis to preceding.sendingTiming)
        assertEquals(
            setOf(
                OrderingKind.START_UP,
                OrderingKind.SHUT_DOWN,
                OrderingKind.ACTIVATION,
                OrderingKind.DEACTIVATION,
                OrderingKind.RESETTING,
            ),
            profile.orderings.keys,
        )
        val beyond = RtsProfiles.read(corpus("beyond-rtsprofile.xml"))
        assertEquals(
            setOf(OrderingKind.ACTIVATION, OrderingKind.INITIALIZING, OrderingKind.FINALIZING),
            beyond.orderings.keys,
        )
        assertEquals(
            "odometry0",
            beyond.components.single().executionContexts.single().participants.single().instanceName,
        )
        assertEquals("odometry0", beyond.components.single().participants.single().instanceName)
        assertEquals("sensors", beyond.groups.single().groupId)
    }

    @Test
    fun `elements and attributes outside the schema are kept`() {
        val profile = RtsProfiles.read(corpus("full-system.xml"))
        val xml = RtsProfiles.write(profile, ProfileFormat.XML)
        assertTrue("""xmlns:vnd="urn:example:vendor"""" in xml && """vnd:build="42"""" in xml, xml)
        assertTrue("""<vnd:Offset vnd:axis="x">0.12</vnd:Offset>""" in xml, xml)
        assertTrue("<rtsExt:VersionUpLogs>first save</rtsExt:VersionUpLogs>" in xml, xml)
        val calibration = profile.components.first().ext.unknownElements.single()
        assertEquals(
            ForeignElement(
                "vnd:Calibration",
                mapOf("vnd:date" to "2024-01-01"),
                listOf(ForeignElement("vnd:Offset", mapOf("vnd:axis" to "x"), text = "0.12")),
            ),
            calibration,
        )
    }

    @Test
    fun `line breaks, tabs and markup in attribute values survive the XML form`() {
        // A reader turns a raw line break or tab in an attribute into a space: they must be written as references.
        val value = "two\nlines\r\tand <markup> & \"quotes\" 'é'"
        val profile =
            RtsProfiles.read(corpus("full-system.xml")).let {
                it.withExt(it.ext.withProperties(mapOf("note" to value)))
            }
        val xml = RtsProfiles.write(profile, ProfileFormat.XML)
        assertEquals(value, RtsProfiles.parse(xml, ProfileFormat.XML, "written").ext.properties["note"], xml)
        assertEquals(profile, RtsProfiles.parse(xml, ProfileFormat.XML, "written"))
    }

    @Test
    fun `what rtsprofile wrote from a file reads as that file, but for what rtsprofile drops`() {
        val ours = RtsProfiles.read(corpus("full-system.xml"))
        val theirs = RtsProfiles.read(corpus("full-system-by-rtsprofile.yaml"))
        // rtsprofile reads compositeType Grouping as None and adds visibility and a location to everything.
        fun ComponentLike(c: ProfileComponent) =
            listOf(
                c.id,
                c.pathUri,
                c.instanceName,
                c.activeConfigurationSet,
                c.isRequired,
                c.dataPorts.map { it.name },
                c.configurationSets,
                c.executionContexts,
                c.ext.properties,
            )
        assertEquals(ours.components.map(::ComponentLike), theirs.components.map(::ComponentLike))
        fun List<PortConnector>.shown() = map { it.withExt(it.ext.withVisible(null)) }
        assertEquals(ours.dataPortConnectors.shown(), theirs.dataPortConnectors.shown())
        assertEquals(ours.servicePortConnectors.shown(), theirs.servicePortConnectors.shown())
        assertEquals(ours.orderings, theirs.orderings)
    }

    @Test
    fun `errors name the file, the line and what is wrong`() {
        val xml =
            "<?xml version=\"1.0\"?>\n<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\" rts:id=\"x\">\n" +
                "  <rts:Components rts:id=\"RTC:a:b:c:1\" rts:pathUri=\"h/c.rtc\"/>\n</rts:RtsProfile>\n"
        val missing = assertThrows<ProfileFormatException> { RtsProfiles.parse(xml, ProfileFormat.XML, "sys.xml") }
        assertEquals("sys.xml:3: rts:Components has no rts:instanceName", missing.message)
        val broken =
            assertThrows<ProfileFormatException> { RtsProfiles.parse("<a>\n<b>\n</a>", ProfileFormat.XML, "bad.xml") }
        assertTrue(broken.message!!.startsWith("bad.xml:3: not well-formed XML"), broken.message)
        val yaml =
            "rtsProfile:\n  id: x\n  components:\n    - id: RTC:a:b:c:1\n      isRequired: maybe\n      instanceName: c\n"
        val bad = assertThrows<ProfileFormatException> { RtsProfiles.parse(yaml, ProfileFormat.YAML, "sys.yaml") }
        assertEquals("sys.yaml:5: isRequired 'maybe' is not true or false", bad.message)
    }

    private fun RtsProfile.withoutForeign(): RtsProfile {
        return withExt(ext.withoutUnknown()).withComponents(components.map { it.withExt(it.ext.withoutUnknown()) })
    }

    private fun corpus(name: String): Path = Paths.get(javaClass.getResource("/profiles/$name")!!.toURI())
}
