package org.rtcoord.internal.logs

import java.time.Instant
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * Node.js's fluent-logger (npm, installed by `scripts/peers.sh` where npm is) sending to [ForwardInput]: the modes,
 * acknowledgements and shared-key handshake Python's client does not have. Each run sends three events and waits for
 * every one's acknowledgement (`requireAckResponse`), so a run that ends well proves the acks came after the events.
 */
class ForwardNodePeerTest {
    @Test
    fun `PackedForward with acks`() {
        ForwardHarness().use { harness -> sendAndCheck(harness, "PackedForward") }
    }

    @Test
    fun `CompressedPackedForward with acks`() {
        ForwardHarness().use { harness -> sendAndCheck(harness, "CompressedPackedForward") }
    }

    @Test
    fun `Message mode with acks and EventTime, after the shared-key handshake`() {
        ForwardHarness { ForwardSettings(it, sharedKey = "component-logs") }
            .use { harness ->
                sendAndCheck(harness, "Message", sharedKey = "component-logs")
            }
    }

    @Test
    fun `PackedForward after the shared-key handshake`() {
        ForwardHarness { ForwardSettings(it, sharedKey = "component-logs") }
            .use { harness ->
                sendAndCheck(harness, "PackedForward", sharedKey = "component-logs")
            }
    }

    @Test
    fun `a wrong shared key is refused with PONG, counted, and nothing is received`() {
        val (node, environment) = NodeFluentLogger.require()
        ForwardHarness { ForwardSettings(it, sharedKey = "component-logs") }
            .use { harness ->
                val port = harness.input.address.port.toString()
                val printed = runScript(listOf(node, "-e", SCRIPT, port, "Message", "not-the-key"), environment)
                assertTrue(printed.contains("refused: Authentication failed: shared key mismatch"), printed)
                assertTrue(harness.awaitRefusal(ForwardRefusal.WRONG_KEY).reason.contains("mismatch"))
                assertTrue(harness.entries.isEmpty())
            }
    }

    private fun sendAndCheck(harness: ForwardHarness, mode: String, sharedKey: String = "") {
        val (node, environment) = NodeFluentLogger.require()
        val port = harness.input.address.port.toString()
        val printed = runScript(listOf(node, "-e", SCRIPT, port, mode, sharedKey), environment)
        assertTrue(printed.contains("acknowledged 3"), printed)
        val entries = harness.awaitEntries(3)
        assertEquals(listOf("rtc.node", "rtc.node", "rtc.node"), entries.map { it.tag })
        assertEquals(listOf(0L, 1L, 2L), entries.map { it.record["index"] })
        assertEquals(listOf("from $mode", "from $mode", "from $mode"), entries.map { it.record["message"] })
        assertEquals(Instant.ofEpochSecond(1_700_000_000, 250_000_000), entries[0].time)
        assertEquals(0L, harness.input.refusals().values.sum())
    }

    private companion object {
        /** Arguments: port, event mode, shared key (empty: none). Prints "acknowledged N" or "refused: why". */
        val SCRIPT =
            """
            const logger = require('fluent-logger');
            const [port, mode, key] = process.argv.slice(1);
            const sender = logger.createFluentSender('rtc', {
              host: '127.0.0.1', port: Number(port), eventMode: mode, timeout: 10,
              requireAckResponse: true, ackResponseTimeout: 20000, reconnectInterval: 600000,
              security: key ? { clientHostname: 'component-host', sharedKey: key } : undefined,
            });
            sender.on('error', (error) => { console.log('refused: ' + error.message); process.exit(0); });
            let acknowledged = 0;
            for (let index = 0; index < 3; index++) {
              const time = new logger.EventTime(1700000000 + index, 250000000);
              sender.emit('node', { message: 'from ' + mode, index }, time, (error) => {
                if (error) { console.log('failed: ' + error); process.exit(3); }
                if (++acknowledged === 3) {
                  console.log('acknowledged 3');
                  sender.end(null, null, () => process.exit(0));
                }
              });
            }
            setTimeout(() => { console.log('timed out: acknowledged ' + acknowledged); process.exit(4); }, 30000);
            """
                .trimIndent()
    }
}
