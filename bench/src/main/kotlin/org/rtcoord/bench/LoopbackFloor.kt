package org.rtcoord.bench

import java.io.DataInputStream
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import kotlin.time.Duration

/**
 * The least a simulated out-port can cost on this machine, measured beside it: [LoopbackWriterMain] in a JVM of its own
 * (C1, one compiler thread and G1, as the launcher runs `rtcoord sim`) sends a sample's bytes to a loopback socket at
 * the port's rate, and this JVM answers each with [REPLY_BYTES], as an in-port answers `put`: no CORBA, no sample made
 * up or encoded. Its cost is its CPU while writing less its CPU with its timer ticking idle, measured in the same pairs
 * of windows as the port: the machine moves both alike, so the port's cost over this floor is what the port adds.
 */
internal class LoopbackFloor(sampleBytes: Int, periodMillis: Long) : AutoCloseable {
    private val server = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).apply { soTimeout = ACCEPT_MILLIS }
    private val process =
        ProcessBuilder(
                listOf(Paths.get(System.getProperty("java.home"), "bin", "java").toString()) +
                    JVM_OPTIONS +
                    listOf(
                        "-cp",
                        System.getProperty("java.class.path"),
                        "org.rtcoord.bench.LoopbackWriterMain",
                        server.localPort.toString(),
                        sampleBytes.toString(),
                        periodMillis.toString(),
                    )
            )
            .redirectError(ProcessBuilder.Redirect.INHERIT)
            .start()
    private val lines = linesOf(process, "loopback-writer-output")
    private val peer: Socket

    init {
        peer =
            try {
                server.accept().apply { tcpNoDelay = true }
            } catch (e: Exception) {
                process.destroyForcibly()
                server.close()
                throw e
            }
        Thread(
                {
                    val samples = DataInputStream(peer.getInputStream())
                    val sample = ByteArray(sampleBytes)
                    val reply = ByteArray(REPLY_BYTES)
                    runCatching {
                        while (true) {
                            samples.readFully(sample)
                            peer.getOutputStream().write(reply)
                        }
                    }
                },
                "loopback-peer",
            )
            .apply {
                isDaemon = true
                start()
            }
    }

    /** Starts or stops the writing, once the writer has taken it. */
    fun writing(on: Boolean) {
        process.outputStream.write(if (on) "write\n".toByteArray() else "idle\n".toByteArray())
        process.outputStream.flush()
        check(lines.poll(ACCEPT_MILLIS.toLong(), TimeUnit.MILLISECONDS) == "ok") {
            "the loopback writer did not answer"
        }
    }

    /** The writer's CPU per second of wall time over [window]. */
    suspend fun cpuPerSecond(window: Duration): Double = cpuPerSecond(window) { sequenceOf(process.toHandle()) }

    override fun close() {
        process.outputStream.close()
        if (!process.waitFor(10, TimeUnit.SECONDS)) process.destroyForcibly().waitFor()
        peer.close()
        server.close()
    }

    companion object {
        /** What the peer answers each sample with: about what an in-port's reply to `put` is. */
        const val REPLY_BYTES = 16
        const val ACCEPT_MILLIS = 30_000
        val JVM_OPTIONS = listOf("-XX:TieredStopAtLevel=1", "-XX:CICompilerCount=1", "-XX:+UseG1GC")
    }
}
