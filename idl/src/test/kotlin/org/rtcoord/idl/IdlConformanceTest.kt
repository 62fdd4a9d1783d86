package org.rtcoord.idl

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import kotlin.streams.asSequence
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * Our IDL declares every type exactly as the reference IDL shipped with rtctree-aist does: repository ids, enumerators,
 * members, inheritance and operation signatures. Both are parsed by omniidl and printed by our `canon` back end, then
 * compared declaration by declaration.
 */
class IdlConformanceTest {
    private val work: Path = Files.createDirectories(Paths.get("target", "idl-conformance").toAbsolutePath())

    /**
     * Declared by OpenRTM-aist but not in rtctree's older IDL: the OpenRTM flavour of the observer (stock components
     * accept it) and the quaternion of OpenRTM-aist 2.0's ExtendedDataTypes.
     */
    private val newerThanReference =
        setOf("OpenRTM::ComponentObserver", "OpenRTM::StatusKind", "RTC::Quaternion", "RTC::TimedQuaternion")

    /**
     * Where OpenRTM-aist 2.0 (C++ and Python alike) corrected InterfaceDataTypes after rtctree's copy was taken; we
     * follow OpenRTM-aist. The bytes on the wire are the same (three or six doubles; a name).
     */
    private val correctedSinceReference =
        setOf(
            "RTC::IntensityData: member 1: `RTC::IntensityList intensities` differs from the reference `RTC::IntensityList ranges`",
            "RTC::Waypoint2D: member 4: `RTC::Velocity2D maxSpeed` differs from the reference `RTC::Pose2D maxSpeed`",
            "RTC::Waypoint3D: member 4: `RTC::Velocity3D maxSpeed` differs from the reference `RTC::Pose3D maxSpeed`",
        )

    @Test
    fun `our declarations match the reference IDL`() {
        val ours = listing(Paths.get("src/main/idl"))
        val reference = listing(referenceIdl())

        val differences = ours.differencesFrom(reference, extras = newerThanReference) - correctedSinceReference
        assertTrue(differences.isEmpty(), "IDL differs from the reference:\n" + differences.joinToString("\n"))
        assertTrue(ours.declarations.size >= 244, "only ${ours.declarations.size} declarations compared")
    }

    @Test
    fun `every data type of the reference is declared`() {
        val ours = listing(Paths.get("src/main/idl")).declarations.keys
        val dataTypes = listOf("BasicDataType.idl", "ExtendedDataTypes.idl", "InterfaceDataTypes.idl")
        val reference = listing(referenceIdl(), only = dataTypes).declarations.keys
        assertTrue(reference.size >= 140, "only ${reference.size} reference data types listed")
        assertEquals(
            emptyList<String>(),
            (reference - ours).toList(),
            "data types the reference declares and ours do not",
        )
    }

    @Test
    fun `the OpenRTM observer is declared as stock components expect it`() {
        val observer = listing(Paths.get("src/main/idl")).declarations
        assertEquals(
            "IDL:OpenRTM/ComponentObserver:1.0",
            observer.getValue("OpenRTM::ComponentObserver")["repository id"],
        )
        assertEquals("SDOPackage::SDOService", observer.getValue("OpenRTM::ComponentObserver")["inherits"])
        assertEquals(
            "oneway void(in OpenRTM::StatusKind, in string)",
            observer.getValue("OpenRTM::ComponentObserver")["operation update_status"],
        )
        assertEquals(
            "COMPONENT_PROFILE, RTC_STATUS, EC_STATUS, PORT_PROFILE, CONFIGURATION, HEARTBEAT, STATUS_KIND_NUM",
            observer.getValue("OpenRTM::StatusKind")["enumerators"],
        )
    }

    /** rtctree-aist's IDL, as `scripts/peers.sh` installed it (the version `scripts/peers-requirements.txt` pins). */
    private fun referenceIdl(): Path = Peers.sitePackage("rtctree").resolve("data/idl")

    /** The declarations of the IDL files in [idlDirectory] ([only] those named, if given) and of what they include. */
    private fun listing(idlDirectory: Path, only: List<String>? = null): IdlListing {
        val files = printed.computeIfAbsent(idlDirectory, ::print).filterKeys { only == null || it in only }
        assertTrue(files.isNotEmpty(), "no IDL in $idlDirectory")
        return IdlListing.parse(
            files.toSortedMap().values.flatten().distinct().filterNot { it.startsWith("CosNotifyComm::") }
        )
    }

    /**
     * Each IDL file of [idlDirectory], by name, as the `canon` back end prints it: one omniidl per file, in parallel.
     */
    private fun print(idlDirectory: Path): Map<String, List<String>> {
        val includes = stubIncludes()
        val files =
            Files.list(idlDirectory).use { paths ->
                paths.asSequence().filter { it.toString().endsWith(".idl") }.toList()
            }
        return files
            .parallelStream()
            .map { file ->
                file.fileName.toString() to
                    run(
                        Peers.tool("omniidl").toString(),
                        "-p",
                        Paths.get("src/test/omniidl").toAbsolutePath().toString(),
                        "-b",
                        "canon",
                        "-I$includes",
                        "-I$idlDirectory",
                        file.toString(),
                    )
            }
            .toList()
            .toMap()
    }

    /** The reference SDO IDL includes two OMG files that are not shipped with it; its types need neither. */
    private fun stubIncludes(): Path {
        val includes = Files.createDirectories(work.resolve("includes"))
        Files.writeString(includes.resolve("orb.idl"), "")
        Files.writeString(
            includes.resolve("CosNotifyComm.idl"),
            "module CosNotifyComm { interface StructuredPushConsumer {}; interface StructuredPushSupplier {}; };\n",
        )
        return includes
    }

    private fun run(vararg command: String): List<String> {
        val process = ProcessBuilder(*command).redirectError(ProcessBuilder.Redirect.PIPE).start()
        val output = process.inputStream.bufferedReader().readLines()
        val errors = process.errorStream.bufferedReader().readText()
        check(process.waitFor(120, TimeUnit.SECONDS)) { "${command.first()} did not finish" }
        check(process.exitValue() == 0) { "${command.joinToString(" ")} failed (${process.exitValue()}): $errors" }
        return output
    }

    private companion object {
        /** What omniidl printed, by directory then file: the tests share it (each listing takes seconds). */
        val printed = ConcurrentHashMap<Path, Map<String, List<String>>>()
    }
}
