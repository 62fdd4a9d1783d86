@file:JvmName("LogSenderMain")

package org.rtcoord.bench

import java.net.InetSocketAddress
import java.util.concurrent.CountDownLatch
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicLong
import java.util.concurrent.locks.LockSupport
import kotlin.system.exitProcess
import org.rtcoord.runtime.FluentLogSender

/**
 * The log benchmark's senders, in a JVM of their own so that their CPU is not the receiving tree's: `PORT MANAGER NAMES
 * SENDERS RATE SECONDS`, each sender a connection of the runtime's [FluentLogSender] (Message mode, one record a call,
 * as OpenRTM-aist-Python's FluentLogger sends) naming the components of NAMES (comma-separated instance names) in turn,
 * all of them together sending RATE records a second for SECONDS; RATE 0: as fast as they can, SECONDS then being how
 * many records each sends. Stops sooner when its standard input ends. Prints `started` once every connection is open
 * and `sent N failed M` at the end.
 */
fun main(args: Array<String>) {
    if (args.size != 6) {
        System.err.println("usage: LogSenderMain PORT MANAGER NAMES SENDERS RATE SECONDS")
        exitProcess(2)
    }
    val address = InetSocketAddress("127.0.0.1", args[0].toInt())
    val names = args[2].split(',')
    val count = args[3].toInt()
    val rate = args[4].toDouble()
    val amount = args[5].toLong()
    val sent = AtomicLong()
    val failed = AtomicLong()
    val senders = List(count) { FluentLogSender(address, args[1]) }
    // Opens every connection before the clock starts: the first record of each connects.
    senders.forEachIndexed { i, sender ->
        if (!sender.send(names[i % names.size], "INFO", "connected")) failed.incrementAndGet()
        else sent.incrementAndGet()
    }
    println("started")
    System.out.flush()
    val stopped = AtomicBoolean()
    Thread(
            {
                System.`in`.readAllBytes()
                stopped.set(true)
            },
            "stop",
        )
        .apply { isDaemon = true }
        .start()
    val done = CountDownLatch(count)
    val start = System.nanoTime()
    senders.forEachIndexed { i, sender ->
        val name = names[i % names.size]
        Thread(
                {
                    if (rate > 0) {
                        // Each sender's records evenly spaced, the senders' phases spread over one period.
                        val period = (1e9 * count / rate).toLong()
                        var due = start + period * i / count
                        val end = start + amount * 1_000_000_000L
                        var n = 0L
                        while (due < end && !stopped.get()) {
                            val wait = due - System.nanoTime()
                            if (wait > 0) LockSupport.parkNanos(wait)
                            if (sender.send(name, LEVELS[(n % LEVELS.size).toInt()], "scan ${n++} ok"))
                                sent.incrementAndGet()
                            else failed.incrementAndGet()
                            due += period
                        }
                    } else {
                        for (n in 0 until amount) {
                            if (stopped.get()) break
                            if (sender.send(name, LEVELS[(n % LEVELS.size).toInt()], "scan $n ok"))
                                sent.incrementAndGet()
                            else failed.incrementAndGet()
                        }
                    }
                    done.countDown()
                },
                "sender-$i",
            )
            .start()
    }
    done.await()
    senders.forEach(FluentLogSender::close)
    println("sent ${sent.get()} failed ${failed.get()}")
    System.out.flush()
    exitProcess(0)
}

/** Mostly INFO, as a component logs, with the odd warning. */
private val LEVELS = listOf("INFO", "INFO", "DEBUG", "INFO", "WARN")
