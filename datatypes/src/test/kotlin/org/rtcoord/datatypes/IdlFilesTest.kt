package org.rtcoord.datatypes

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** Users' IDL read with JacORB's parser: every construct a data type can use, and what goes wrong. */
class IdlFilesTest {
    private val idl: Path = Paths.get(javaClass.getResource("/idl")!!.toURI())

    @Test
    fun `a user's struct with a union, an enum, sequences, arrays, typedefs and nested modules`() {
        val types = IdlFiles.readDirectory(idl.resolve("acme"))
        val status = types.named("IDL:Acme/Sensing/Status:1.0") as IdlType.Struct
        assertEquals("Acme::Sensing::Status", status.name)
        assertEquals(
            "struct IDL:Acme/Sensing/Status:1.0 Acme::Sensing::Status {" +
                "struct IDL:RTC/Time:1.0 RTC::Time {unsigned long sec; unsigned long nsec} tm; " +
                "enum IDL:Acme/Sensing/Health:1.0 Acme::Sensing::Health {OK, DEGRADED, FAILED} state; " +
                "union IDL:Acme/Sensing/Reading:1.0 Acme::Sensing::Reading switch(IDL:Acme/Sensing/Health:1.0) " +
                "{OK: double value; DEGRADED: string reason; default: long code} sample; " +
                "typedef IDL:Acme/Sensing/Matrix3:1.0 Acme::Sensing::Matrix3 double[3][3] rotation; " +
                "typedef IDL:Acme/Sensing/Blobs:1.0 Acme::Sensing::Blobs sequence<struct IDL:Acme/Common/Blob:1.0 Acme::Common::Blob " +
                "{short id; sequence<octet, 0> bytes}, 4> parts; " +
                "char[2] tags; wstring label; unsigned long long serial}",
            status.describe(),
        )
        assertTrue(
            types.types.keys.containsAll(listOf("IDL:Acme/Common/Blob:1.0", "IDL:RTC/TimedLong:1.0")),
            "included files' types too",
        )
    }

    @Test
    fun `a user's type survives the codec in both byte orders, whichever union case it holds`() {
        val status = IdlFiles.readDirectory(idl.resolve("acme")).named("Acme::Sensing::Status")!!
        val codec = DataCodec(status)
        val values = MadeUpValues(status, seed = 11)
        val cases = mutableSetOf<Any?>()
        for (second in 0L until 4) {
            val value = values.at(second * 1_000_000_000) as Map<*, *>
            cases += (value["sample"] as Map<*, *>)[IdlType.UNION_DISCRIMINATOR]
            for (littleEndian in listOf(true, false)) {
                assertEquals(flatten(value), flatten(codec.decode(codec.encode(value, littleEndian), littleEndian)))
            }
        }
        assertEquals(setOf("OK", "DEGRADED"), cases)
    }

    @Test
    fun `malformed IDL is one line naming the file, the line and the reason, and the other files are read`() {
        val read = IdlFiles.readDirectories(listOf(idl.resolve("broken"), idl.resolve("acme")))
        assertTrue(read.named("Acme::Sensing::Status") is IdlType.Struct)
        val message = read.errors.single()
        assertFalse(message.contains('\n'), message)
        assertTrue(message.contains("Broken.idl:4:"), message)
        assertTrue(message.contains("doubel"), message)
    }

    @Test
    fun `a missing include is named`(@org.junit.jupiter.api.io.TempDir directory: Path) {
        Files.writeString(
            directory.resolve("Lonely.idl"),
            "#include \"Nowhere.idl\"\nmodule Lonely { struct S { long x; }; };\n",
        )
        val message = IdlFiles.readDirectory(directory).errors.single()
        assertTrue(message.contains("Nowhere.idl"), message)
        assertFalse(message.contains('\n'), message)
    }

    @Test
    fun `a directory without IDL, or none at all, is named`(@org.junit.jupiter.api.io.TempDir directory: Path) {
        assertEquals(listOf("$directory: no .idl file in it"), IdlFiles.readDirectory(directory).errors)
        assertEquals(
            listOf("${directory.resolve("nowhere")}: not a directory"),
            IdlFiles.readDirectory(directory.resolve("nowhere")).errors,
        )
    }

    private fun flatten(value: Any?): Any? =
        when (value) {
            is Map<*, *> -> value.mapValues { flatten(it.value) }
            is DoubleArray -> value.toList().map(::flatten)
            is ByteArray -> value.toList().map(::flatten)
            is List<*> -> value.map(::flatten)
            is Number -> if (value is Double || value is Float) value.toDouble() else value.toLong()
            else -> value
        }
}
