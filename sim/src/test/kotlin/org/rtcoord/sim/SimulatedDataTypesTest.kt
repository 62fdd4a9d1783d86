package org.rtcoord.sim

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.LifeCycleState
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.StructuredData
import org.rtcoord.TimedPose2D
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.Coordinator
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.Sample

/** Ports of OpenRTM-aist's device types and of a user's own IDL, simulated, connected and sending. */
class SimulatedDataTypesTest {
    @Test
    fun `every port of a known type sends, a port of a type with no IDL is kept and says once it sends nothing`() {
        SimulatedSystem.start(TypedSystem.profile(), idlDirectories = listOf(TypedSystem.acmeIdl)).use { sim ->
            sim.components.forEach { assertEquals(LifeCycleState.ACTIVE_STATE, it.state, it.instanceName) }
            assertEquals(
                listOf(
                    "mystery0.blob: sends no data: its data type IDL:Mystery/Blob:1.0 is not one of OpenRTM-aist's and no IDL " +
                        "given declares it (give the directory of its IDL: rtcoord sim --idl DIR, or idl(\"DIR\") in a test)"
                ),
                sim.warnings,
            )
            val viewer = sim.component("viewer0")
            val first = awaitSample(viewer, "pose", after = null)
            val second = awaitSample(viewer, "pose", after = first)
            val pose = second.value as Map<*, *>
            assertEquals(setOf("position", "heading"), pose.keys)
            assertTrue(second.timeNanos > first.timeNanos, "time-stamped as written")
            assertTrue(pose != first.value, "the pose changes from sample to sample")
            assertEquals(null, viewer.latest("blob"), "the type without IDL sent nothing")
        }
    }

    @Test
    fun `a connector between ports of different types is left out with one line, the rest runs`() {
        val profile = TypedSystem.profile(listOf(Triple("ranger0.range", "viewer0.pose", "IDL:RTC/RangeData:1.0")))
        SimulatedSystem.start(profile, idlDirectories = listOf(TypedSystem.acmeIdl)).use { sim ->
            assertTrue(
                "connector ranger0.range_viewer0.pose (ranger0.range to viewer0.pose): left out: it joins IDL:RTC/RangeData:1.0 " +
                    "to IDL:RTC/TimedPose2D:1.0, which OpenRTM-aist refuses to connect" in sim.warnings,
                sim.warnings.toString(),
            )
            awaitSample(sim.component("viewer0"), "pose", after = null)
        }
    }

    @Test
    fun `a malformed IDL file is a warning naming it, the types of the others are simulated`() {
        val broken = kotlin.io.path.createTempDirectory("rtcoord-broken-idl")
        try {
            kotlin.io.path
                .Path(broken.toString(), "Broken.idl")
                .toFile()
                .writeText("module Broken {\n  struct Half { doubel y; };\n};\n")
            SimulatedSystem.start(TypedSystem.profile(), idlDirectories = listOf(broken, TypedSystem.acmeIdl)).use { sim
                ->
                val first = sim.warnings.first()
                assertTrue(
                    first.startsWith("$broken/Broken.idl:2: ") && first.contains("doubel") && '\n' !in first,
                    first,
                )
                assertEquals(2, sim.warnings.size, sim.warnings.toString())
            }
        } finally {
            broken.toFile().deleteRecursively()
        }
    }

    @Test
    fun `an out-port sends in the byte order its connector chose`() {
        SimulatedSystem.start(TypedSystem.profile(), idlDirectories = listOf(TypedSystem.acmeIdl)).use { sim ->
            val viewer = sim.component("viewer0")
            val source = sim.component("odometry0").ref.get_ports().single()
            val target = viewer.ref.get_ports().first { it.get_port_profile().name == "viewer0.pose" }
            assertEquals(ReturnCode_t.RTC_OK, source.disconnect_all())
            val orb = org.omg.CORBA.ORB.init()
            val properties =
                mapOf(
                        "dataport.dataflow_type" to "push",
                        "dataport.interface_type" to "corba_cdr",
                        "dataport.subscription_type" to "new",
                        "dataport.data_type" to "IDL:RTC/TimedPose2D:1.0",
                        "dataport.serializer.cdr.endian" to "big,little",
                    )
                    .map { (name, value) -> NameValue(name, orb.create_any().apply { insert_string(value) }) }
            val holder =
                ConnectorProfileHolder(ConnectorProfile("big", "", arrayOf(source, target), properties.toTypedArray()))
            val before = viewer.latest("pose")
            assertEquals(ReturnCode_t.RTC_OK, source.connect(holder))
            val sample = awaitSample(viewer, "pose", after = before)
            val now = System.currentTimeMillis() * 1_000_000
            assertTrue(
                sample.timeNanos in now - 10_000_000_000..now,
                "a time stamp read in the right order: ${sample.timeNanos}",
            )
        }
    }

    @Test
    fun `a coordinator's data rules see the device types decoded, and every sample differs`(): Unit = runBlocking {
        SimulatedSystem.start(TypedSystem.profile(), idlDirectories = listOf(TypedSystem.acmeIdl)).use { sim ->
            val config = TreeConfig(listOf(sim.address))
            RtcTree(config).use { tree ->
                val scans = Channel<StructuredData>(Channel.UNLIMITED)
                val poses = Channel<TimedPose2D>(Channel.UNLIMITED)
                val coordination =
                    Coordination(emptyList(), config).apply {
                        on(port("ranger0.rtc:range")).data<StructuredData> { scans.trySend(it) }
                        on(port("odometry0.rtc:odo")).data<TimedPose2D> { poses.trySend(it) }
                    }
                Coordinator(tree, coordination, EventOptions(WatchMode.PUSH)).use { coordinator ->
                    coordinator.start()
                    withTimeout(20.seconds) {
                        val first = scans.receive()
                        val second = scans.receive()
                        assertEquals("IDL:RTC/RangeData:1.0", first.typeName)
                        val ranges = first.member("ranges") as List<*>
                        assertEquals(1081, ranges.size)
                        assertTrue(ranges.all { it as Double in 0.02..30.0 }, "within the ranger's limits")
                        assertTrue(first.member("ranges") != second.member("ranges"), "each scan differs")
                        assertTrue(second.time!! > first.time!!)
                        val pose = poses.receive()
                        assertTrue(pose.heading.isFinite() && pose.x.isFinite())
                    }
                }
            }
        }
    }

    private fun awaitSample(component: RuntimeComponent, port: String, after: Sample?): Sample {
        var sample: Sample? = null
        await("a new sample at ${component.instanceName}.$port") {
            sample = component.latest(port)?.takeIf { it != after && (after == null || it.timeNanos > after.timeNanos) }
            sample != null
        }
        return sample!!
    }
}
