package org.rtcoord.internal.logs

import java.time.Instant
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.Peers

/**
 * Python's fluent-logger (PyPI, pinned in `scripts/peers-requirements.txt`), the client OpenRTM-aist-Python's
 * `FluentLogger` sends component logs through, sending to [ForwardInput]: Message mode, with and without
 * `nanosecond_precision`, and a log record shaped as `FluentLogger` shapes it.
 */
class ForwardPythonPeerTest {
    @Test
    fun `fluent-logger's sender and OpenRTM-aist's record shape arrive whole`() {
        val python = Peers.require("python")
        ForwardHarness().use { harness ->
            val before = Instant.now()
            runScript(listOf(python.toString(), "-c", SCRIPT, harness.input.address.port.toString()))
            val after = Instant.now()

            val plain = harness.awaitTagged("rtc.plain")
            assertEquals(Instant.ofEpochSecond(1_700_000_000), plain.time)
            assertEquals(
                mapOf(
                    "message" to "hello",
                    "count" to 3L,
                    "ratio" to 0.5,
                    "ok" to true,
                    "none" to null,
                    "items" to listOf(1L, "two"),
                    "nested" to mapOf("k" to "v"),
                ),
                plain.record,
            )
            // nanosecond_precision: an EventTime, to the nanosecond.
            assertEquals(Instant.ofEpochSecond(1_700_000_000, 123_456_789), harness.awaitTagged("rtc.precise").time)
            val now = harness.awaitTagged("rtc.now").time
            assertTrue(now >= before.minusSeconds(1) && now <= after, "$now within the run")

            // FluentLogger.py's handler and formatter, with its fmt keys.
            val log = harness.awaitTagged("rtc.logger")
            assertEquals("WARNING", log.record["level"])
            assertEquals("fluent.ConsoleIn0", log.record["name"])
            assertEquals("onExecute took too long", log.record["message"])
            assertTrue((log.record["pid"] as String).toInt() > 0, log.record.toString())
            assertEquals(setOf("time", "name", "level", "pid", "host", "message"), log.record.keys)
            assertEquals(4, harness.entries.size)
            assertEquals(0L, harness.input.refusals().values.sum())
        }
    }

    private companion object {
        val SCRIPT =
            """
            import logging, sys
            from fluent import handler, sender
            port = int(sys.argv[1])

            def sent(ok, client):
                if not ok:
                    raise SystemExit("not sent: %r" % client.last_error)

            plain = sender.FluentSender("rtc", host="127.0.0.1", port=port)
            record = {"message": "hello", "count": 3, "ratio": 0.5, "ok": True, "none": None,
                      "items": [1, "two"], "nested": {"k": "v"}}
            sent(plain.emit_with_time("plain", 1700000000, record), plain)
            plain.close()

            nano = sender.FluentSender("rtc", host="127.0.0.1", port=port, nanosecond_precision=True)
            sent(nano.emit_with_time("precise", sender.EventTime.from_unix_nano(1700000000123456789),
                                     {"message": "precise"}), nano)
            sent(nano.emit("now", {"message": "now"}), nano)
            nano.close()

            # As OpenRTM_aist/ext/logger/fluentlogger/FluentLogger.py sets it up.
            fhdlr = handler.FluentHandler("rtc.logger", host="127.0.0.1", port=port)
            fhdlr.setFormatter(handler.FluentRecordFormatter(fmt={
                "time": "%(asctime)s", "name": "%(name)s", "level": "%(levelname)s",
                "pid": "%(process)d", "host": "%(hostname)s"}))
            log = logging.getLogger("fluent.ConsoleIn0")
            log.addHandler(fhdlr)
            log.setLevel(logging.INFO)
            log.warning("onExecute took too long")
            fhdlr.close()
            """
                .trimIndent()
    }
}
