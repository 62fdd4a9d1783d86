@file:JvmName("LoopbackWriterMain")

package org.rtcoord.bench

import java.io.DataInputStream
import java.net.InetAddress
import java.net.Socket
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import kotlin.system.exitProcess

/**
 * The loopback floor's writer ([LoopbackFloor]), in a JVM of its own as `rtcoord sim` is: `PORT BYTES PERIOD_MS`. A
 * timer ticks every PERIOD_MS and, while writing, sends BYTES to the peer on PORT (127.0.0.1) from its thread; another
 * thread reads the peer's 16-byte answers, as a JacORB connection's reader reads the replies to `put`. Reads `write`
 * and `idle` from its standard input, answering each with `ok`; ends with it.
 */
fun main(args: Array<String>) {
    if (args.size != 3) {
        System.err.println("usage: LoopbackWriterMain PORT BYTES PERIOD_MS")
        exitProcess(2)
    }
    val socket = Socket(InetAddress.getLoopbackAddress(), args[0].toInt()).apply { tcpNoDelay = true }
    val sample = ByteArray(args[1].toInt())
    val output = socket.getOutputStream()
    Thread(
            {
                val replies = DataInputStream(socket.getInputStream())
                val reply = ByteArray(LoopbackFloor.REPLY_BYTES)
                runCatching { while (true) replies.readFully(reply) }
            },
            "loopback-replies",
        )
        .apply {
            isDaemon = true
            start()
        }
    val writing = AtomicBoolean()
    val timer = Executors.newSingleThreadScheduledExecutor { Thread(it, "loopback-timer").apply { isDaemon = true } }
    val period = args[2].toLong()
    timer.scheduleAtFixedRate({ if (writing.get()) output.write(sample) }, period, period, TimeUnit.MILLISECONDS)
    System.`in`.bufferedReader().forEachLine { line ->
        writing.set(line == "write")
        println("ok")
        System.out.flush()
    }
    socket.close()
}
