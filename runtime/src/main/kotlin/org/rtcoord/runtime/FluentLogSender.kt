package org.rtcoord.runtime

import java.io.IOException
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import java.nio.ByteBuffer
import java.time.Instant
import java.time.ZoneId
import java.time.format.DateTimeFormatter
import java.util.Locale
import org.msgpack.core.MessagePack

/**
 * Sends a process's log records to a Fluentd forward input at [address], as OpenRTM-aist's C++ `fluentbit_stream` sends
 * them (`src/ext/logger/fluentbit_stream/FluentBit.cpp`): tagged [tag], each record's values all strings, `time` (the
 * logger's own date), `name` (a component's logger is named by its instance name, `RTObject_impl::setInstanceName`),
 * `level`, `pid`, `host`, `manager` (`manager.instance_name`) and `message`; in the forward protocol's Message mode
 * with a nanosecond EventTime, as Fluent Bit's forward output sends.
 *
 * A record that cannot be sent (nobody listens) is dropped after one new attempt to connect, as a logger must never
 * stall the component that logs.
 */
public class FluentLogSender(
    private val address: InetSocketAddress,
    private val manager: String,
    private val tag: String = "rtclog",
) : AutoCloseable {
    private var socket: Socket? = null
    private val host = runCatching { InetAddress.getLocalHost().hostName }.getOrDefault("localhost")
    private val pid = ProcessHandle.current().pid().toString()

    /** Sends one record of logger [name] at [level] (`WARN`, `ERROR`, ...); returns whether it was sent. */
    @Synchronized
    public fun send(name: String, level: String, message: String): Boolean {
        val bytes = encode(name, level, message, Instant.now())
        repeat(2) {
            try {
                val open = socket ?: Socket().also { it.connect(address, CONNECT_MILLIS) }.also { socket = it }
                open.getOutputStream().apply {
                    write(bytes)
                    flush()
                }
                return true
            } catch (e: IOException) {
                closeSocket()
            }
        }
        return false
    }

    private fun encode(name: String, level: String, message: String, now: Instant): ByteArray {
        val record =
            linkedMapOf(
                "time" to DATE.format(now),
                "name" to name,
                "level" to level,
                "pid" to pid,
                "host" to host,
                "manager" to manager,
                "message" to message,
            )
        MessagePack.newDefaultBufferPacker().use { packer ->
            packer.packArrayHeader(3)
            packer.packString(tag)
            val time = ByteBuffer.allocate(8).putInt(now.epochSecond.toInt()).putInt(now.nano).array()
            packer.packExtensionTypeHeader(EVENT_TIME, time.size)
            packer.writePayload(time)
            packer.packMapHeader(record.size)
            record.forEach { (key, value) ->
                packer.packString(key)
                packer.packString(value)
            }
            return packer.toByteArray()
        }
    }

    @Synchronized
    override fun close() {
        closeSocket()
    }

    private fun closeSocket() {
        socket?.close()
        socket = null
    }

    private companion object {
        /** The forward protocol's EventTime extension type. */
        const val EVENT_TIME: Byte = 0
        const val CONNECT_MILLIS = 1000
        /** The date OpenRTM-aist's C++ logger writes (`logger.date_format`'s default, `%b %d %H:%M:%S.%Q`). */
        val DATE: DateTimeFormatter =
            DateTimeFormatter.ofPattern("MMM dd HH:mm:ss.SSS", Locale.ROOT).withZone(ZoneId.systemDefault())
    }
}
