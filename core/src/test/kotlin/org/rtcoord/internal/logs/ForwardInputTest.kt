package org.rtcoord.internal.logs

import java.io.ByteArrayOutputStream
import java.net.BindException
import java.net.ConnectException
import java.net.DatagramPacket
import java.net.DatagramSocket
import java.net.InetSocketAddress
import java.time.Instant
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.zip.GZIPOutputStream
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import org.junit.jupiter.api.Assertions.assertArrayEquals
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.msgpack.core.MessagePack
import org.rtcoord.fixtures.await

/** [ForwardInput] driven by the tests' own msgpack-core client, for what the real clients do not send. */
class ForwardInputTest {
    @Test
    fun `Forward mode hands every entry on in order, with each kind of time and value, then acknowledges`() {
        ForwardHarness().use { harness ->
            ForwardTestClient(harness.input.address).use { client ->
                client.send {
                    packArrayHeader(3).packString("rtc.forward").packArrayHeader(4)
                    entry(1_700_000_000, "integer seconds")
                    packArrayHeader(2).eventTime(1_700_000_001, 250_000_000)
                    packMapHeader(1).packString("message").packString("EventTime")
                    packArrayHeader(2).packDouble(1_700_000_002.5)
                    packMapHeader(1).packString("message").packString("float seconds")
                    // A record of every value MessagePack has, one key sent as bin as old fluent-loggers send keys.
                    packArrayHeader(2).packLong(1_700_000_003).packMapHeader(7)
                    packBinaryHeader(5).writePayload("level".toByteArray()).packString("WARN")
                    packString("count").packLong(-3)
                    packString("ratio").packDouble(0.5)
                    packString("ok").packBoolean(true)
                    packString("none").packNil()
                    packString("raw").packBinaryHeader(2).writePayload(byteArrayOf(1, 2))
                    packString("nested").packMapHeader(1).packString("list").packArrayHeader(2).packLong(1)
                    packString("two")
                    packMapHeader(1).packString("chunk").packString("c-1")
                }
                assertEquals("""{"ack":"c-1"}""", client.receive().toJson())
                // The acknowledgement follows the entries' handing on: they are all there already.
                val entries = harness.entries.toList()
                assertEquals(4, entries.size, entries.toString())
                assertEquals(List(4) { "rtc.forward" }, entries.map { it.tag })
                assertEquals(
                    listOf(
                        Instant.ofEpochSecond(1_700_000_000),
                        Instant.ofEpochSecond(1_700_000_001, 250_000_000),
                        Instant.ofEpochSecond(1_700_000_002, 500_000_000),
                        Instant.ofEpochSecond(1_700_000_003),
                    ),
                    entries.map { it.time },
                )
                assertEquals("EventTime", entries[1].record["message"])
                val record = entries[3].record
                assertEquals("WARN", record["level"])
                assertEquals(-3L, record["count"])
                assertEquals(0.5, record["ratio"])
                assertEquals(true, record["ok"])
                assertTrue(record.containsKey("none") && record["none"] == null)
                assertArrayEquals(byteArrayOf(1, 2), record["raw"] as ByteArray)
                assertEquals(mapOf("list" to listOf(1L, "two")), record["nested"])
                assertEquals(client.socket.localSocketAddress, entries[0].sender)
            }
            assertEquals(0L, harness.input.refusals().values.sum())
        }
    }

    @Test
    fun `PackedForward reads entries sent as str, and gzip of several members concatenated`() {
        ForwardHarness().use { harness ->
            ForwardTestClient(harness.input.address).use { client ->
                val plain = packed { entry(1, "first") }
                client.send {
                    packArrayHeader(2).packString("rtc.str").packRawStringHeader(plain.size).addPayload(plain)
                }
                // Two gzip members, as a sender appending compressed chunks writes them.
                val gzipped =
                    gzip(packed { entry(2, "second") }) + gzip(packed { entry(3, "third").entry(4, "fourth") })
                client.send {
                    packArrayHeader(3).packString("rtc.gzip").packBinaryHeader(gzipped.size).addPayload(gzipped)
                    packMapHeader(2).packString("compressed").packString("gzip").packString("chunk").packString("c-2")
                }
                assertEquals("""{"ack":"c-2"}""", client.receive().toJson())
                assertEquals(
                    listOf("first", "second", "third", "fourth"),
                    harness.entries.map { it.record["message"] },
                )
                assertEquals(listOf("rtc.str", "rtc.gzip", "rtc.gzip", "rtc.gzip"), harness.entries.map { it.tag })
            }
        }
    }

    @Test
    fun `frames that come in pieces, several at once, or larger than a read are handed on whole and in order`() {
        ForwardHarness().use { harness ->
            ForwardTestClient(harness.input.address).use { client ->
                val small = packed { packArrayHeader(3).packString("piece").packLong(1).packMapHeader(0) }
                // A byte at a time: whatever the reads see, the frame is decoded once.
                small.forEach { client.sendRaw(byteArrayOf(it)) }
                // Two frames in one write.
                client.sendRaw(small + small)
                // About 600 KB in one frame: several reads of the input's 64 KiB.
                client.send {
                    packArrayHeader(3).packString("large").packArrayHeader(2000)
                    repeat(2000) { entry(1, "$it ".padEnd(300, 'x')) }
                    packMapHeader(1).packString("chunk").packString("large-1")
                }
                assertEquals("""{"ack":"large-1"}""", client.receive().toJson())
                assertEquals(listOf("piece", "piece", "piece"), harness.entries.take(3).map { it.tag })
                val large = harness.entries.drop(3)
                assertEquals(
                    (0 until 2000).map { "$it" },
                    large.map { (it.record["message"] as String).substringBefore(' ') },
                )
                assertTrue(large.all { (it.record["message"] as String).length == 300 })
            }
            assertEquals(0L, harness.input.refusals().values.sum())
        }
    }

    @Test
    fun `malformed MessagePack closes that connection only and is counted`() {
        ForwardHarness().use { harness ->
            ForwardTestClient(harness.input.address).use { good ->
                ForwardTestClient(harness.input.address).use { bad ->
                    message(good, "before")
                    harness.awaitTagged("before")
                    // 0xc1 is the one byte MessagePack never uses.
                    bad.sendRaw(byteArrayOf(0xc1.toByte()))
                    assertEquals(ForwardRefusal.MALFORMED, harness.awaitRefusal(ForwardRefusal.MALFORMED).refusal)
                    assertTrue(bad.closedByServer())
                    // A well-formed value that is not a frame is refused the same way.
                    ForwardTestClient(harness.input.address).use { notFrame ->
                        notFrame.send { packMapHeader(0) }
                        assertTrue(notFrame.closedByServer())
                    }
                    message(good, "after")
                    harness.awaitTagged("after")
                }
            }
            assertEquals(2L, harness.input.refusals()[ForwardRefusal.MALFORMED])
            assertEquals(listOf("before", "after"), harness.entries.map { it.tag })
        }
    }

    @Test
    fun `a frame over maxRecordBytes is refused, before a declared size is read or allocated`() {
        ForwardHarness { ForwardSettings(it, maxRecordBytes = 1024) }
            .use { harness ->
                ForwardTestClient(harness.input.address).use { client ->
                    client.sendUntilRefused(
                        packed {
                            packArrayHeader(3).packString("big").packLong(1).packMapHeader(1).packString("message")
                            packString("x".repeat(2000))
                        }
                    )
                    assertTrue(harness.awaitRefusal(ForwardRefusal.TOO_LARGE).reason.contains("1024"))
                    assertTrue(client.closedByServer())
                }
                ForwardTestClient(harness.input.address).use { client ->
                    // A bin 32 header declaring 2 GiB and nothing after it: refused on the header alone.
                    client.sendRaw(
                        byteArrayOf(0x93.toByte(), 0xa1.toByte(), 't'.code.toByte(), 0xc6.toByte(), 0x7f, -1, -1, -1)
                    )
                    assertTrue(client.closedByServer())
                }
                ForwardTestClient(harness.input.address).use { client ->
                    // An entry that unpacks past the limit from a small gzip.
                    val bomb =
                        gzip(
                            packed {
                                packArrayHeader(2)
                                    .packLong(1)
                                    .packMapHeader(1)
                                    .packString("m")
                                    .packString("y".repeat(4096))
                            }
                        )
                    client.send {
                        packArrayHeader(3).packString("bomb").packBinaryHeader(bomb.size).addPayload(bomb)
                        packMapHeader(1).packString("compressed").packString("gzip")
                    }
                    assertTrue(client.closedByServer())
                }
                await("three refusals as too large") { harness.input.refusals()[ForwardRefusal.TOO_LARGE] == 3L }
                assertTrue(harness.entries.isEmpty())
            }
    }

    @Test
    fun `a connection sending more than maxEntriesPerSecond is refused as a flood`() {
        ForwardHarness { ForwardSettings(it, maxEntriesPerSecond = 100) }
            .use { harness ->
                ForwardTestClient(harness.input.address).use { client ->
                    client.sendUntilRefused(
                        packed {
                            packArrayHeader(2).packString("flood").packArrayHeader(1000)
                            repeat(1000) { entry(1, "entry $it") }
                        }
                    )
                    assertTrue(harness.awaitRefusal(ForwardRefusal.FLOOD).reason.contains("100"))
                    assertTrue(client.closedByServer())
                }
                assertEquals(100, harness.entries.size)
            }
    }

    @Test
    fun `a frame begun and not completed is refused after frameTimeout, while another connection goes on`() {
        ForwardHarness { ForwardSettings(it, frameTimeout = 300.milliseconds) }
            .use { harness ->
                ForwardTestClient(harness.input.address).use { good ->
                    ForwardTestClient(harness.input.address).use { stalled ->
                        // The frame's array header and tag, and never the rest.
                        stalled.send { packArrayHeader(3).packString("stalled") }
                        // Meanwhile the good connection is served, frame after frame, acknowledged.
                        good.send {
                            packArrayHeader(4).packString("good").packLong(1).packMapHeader(0)
                            packMapHeader(1).packString("chunk").packString("g-1")
                        }
                        assertEquals("""{"ack":"g-1"}""", good.receive().toJson())
                        val refused = harness.awaitRefusal(ForwardRefusal.INCOMPLETE_FRAME)
                        assertEquals(stalled.socket.localSocketAddress, refused.sender)
                        assertTrue(stalled.closedByServer())
                        good.send {
                            packArrayHeader(4).packString("good").packLong(2).packMapHeader(0)
                            packMapHeader(1).packString("chunk").packString("g-2")
                        }
                        assertEquals("""{"ack":"g-2"}""", good.receive().toJson())
                    }
                }
                assertEquals(2, harness.entries.size)
                assertEquals(
                    mapOf(ForwardRefusal.INCOMPLETE_FRAME to 1L),
                    harness.input.refusals().filterValues { it > 0 },
                )
            }
    }

    @Test
    fun `heartbeats are answered on UDP and accepted on TCP without a refusal`() {
        ForwardHarness().use { harness ->
            DatagramSocket().use { udp ->
                udp.soTimeout = 10_000
                udp.send(DatagramPacket(byteArrayOf(0), 1, harness.input.address))
                val answer = DatagramPacket(ByteArray(16), 16)
                udp.receive(answer)
                assertArrayEquals(byteArrayOf(0), answer.data.copyOf(answer.length))
            }
            // out_forward's TCP heartbeat: a connection that opens and closes; and a nil frame.
            ForwardTestClient(harness.input.address).close()
            ForwardTestClient(harness.input.address).use { client ->
                client.send { packNil() }
                message(client, "marker")
                harness.awaitTagged("marker")
            }
            assertEquals(1, harness.entries.size)
            assertEquals(0L, harness.input.refusals().values.sum())
        }
    }

    @Test
    fun `with a shared key, events before the handshake are refused as a wrong key`() {
        ForwardHarness { ForwardSettings(it, sharedKey = "secret") }
            .use { harness ->
                ForwardTestClient(harness.input.address).use { client ->
                    val helo = client.receive().asArrayValue()
                    assertEquals("HELO", helo[0].toString())
                    val options = helo[1].asMapValue().map().mapKeys { it.key.toString() }
                    assertEquals(16, options.getValue("nonce").asBinaryValue().asByteArray().size)
                    message(client, "unauthenticated")
                    val pong = client.receive().asArrayValue()
                    assertEquals(listOf("PONG", "false"), listOf(pong[0].toString(), pong[1].toString()))
                    assertTrue(client.closedByServer())
                }
                harness.awaitRefusal(ForwardRefusal.WRONG_KEY)
                assertTrue(harness.entries.isEmpty())
            }
    }

    @Test
    fun `a callback that throws closes that connection only, and the input serves the others`() {
        val job = SupervisorJob()
        val received = ConcurrentLinkedQueue<ForwardEntry>()
        val settings = ForwardSettings(InetSocketAddress("127.0.0.1", 0))
        val receiving = { entry: ForwardEntry ->
            check(entry.tag != "boom") { "the callback's own bug" }
            received += entry
        }
        ForwardInput(CoroutineScope(job + Dispatchers.Default), settings, receiving) { _, _, _ -> }
            .use { input ->
                ForwardTestClient(input.address).use { good ->
                    ForwardTestClient(input.address).use { unlucky ->
                        message(unlucky, "boom")
                        assertTrue(unlucky.closedByServer())
                        message(good, "after")
                        await("the other connection's entry") { received.any { it.tag == "after" } }
                    }
                }
                assertEquals(0L, input.refusals().values.sum(), "not the sender's doing")
            }
        job.cancel()
    }

    @Test
    fun `close ends the listener, every connection and every coroutine`() {
        val harness = ForwardHarness()
        val address = harness.input.address
        val client = ForwardTestClient(address)
        message(client, "open")
        harness.awaitTagged("open")
        harness.input.close()
        assertTrue(harness.job.children.none(), "the input's job ended with close")
        assertTrue(client.closedByServer())
        assertThrows<ConnectException> { ForwardTestClient(address).close() }
        // The UDP port is free again.
        DatagramSocket(address).close()
        harness.input.close()
        client.close()
        harness.close()
    }

    @Test
    fun `cancelling the scope closes the input's sockets`() {
        val harness = ForwardHarness()
        val client = ForwardTestClient(harness.input.address)
        message(client, "open")
        harness.awaitTagged("open")
        harness.job.cancel()
        assertTrue(client.closedByServer())
        await("the input's coroutines ended") { harness.job.children.none() }
        client.close()
        harness.close()
    }

    @Test
    fun `an address in use is refused with a BindException naming it`() {
        ForwardHarness().use { harness ->
            val taken = harness.input.address
            val error =
                assertThrows<BindException> {
                    ForwardInput(harness.scope, ForwardSettings(taken), {}, { _, _, _ -> })
                }
            assertTrue(error.message!!.contains(taken.toString()), error.message)
            assertEquals(1, harness.job.children.count(), "the refused input left nothing in the scope")
        }
    }

    private fun message(client: ForwardTestClient, tag: String) = client.send {
        packArrayHeader(3).packString(tag).packLong(1).packMapHeader(0)
    }

    private fun packed(write: org.msgpack.core.MessagePacker.() -> Unit): ByteArray {
        val bytes = ByteArrayOutputStream()
        MessagePack.newDefaultPacker(bytes).apply(write).close()
        return bytes.toByteArray()
    }

    private fun gzip(bytes: ByteArray): ByteArray {
        val out = ByteArrayOutputStream()
        GZIPOutputStream(out).use { it.write(bytes) }
        return out.toByteArray()
    }
}
