package org.rtcoord.runtime

import OpenRTM.InPortCdr
import OpenRTM.PortStatus
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.launch
import org.slf4j.LoggerFactory

/**
 * Sends an out-port's samples, encoded in its connector's byte order, to one connected in-port, from its own coroutine,
 * keeping only the newest sample when the peer is slower than the writer (OpenRTM's `new` push policy). A slow or dead
 * peer never blocks the writing component.
 */
internal class Publisher(
    private val target: InPortCdr,
    component: RuntimeComponent,
    private val port: String,
    /** The byte order the connector negotiated (`dataport.serializer.cdr.endian`). */
    val littleEndian: Boolean,
) {
    private val log = LoggerFactory.getLogger(Publisher::class.java)
    private val pending = Channel<ByteArray>(Channel.CONFLATED)

    init {
        component.scope.launch {
            for (data in pending) {
                try {
                    val status = target.put(data)
                    if (status != PortStatus.PORT_OK) log.debug("{}: peer answered {}", port, status.value())
                } catch (e: org.omg.CORBA.SystemException) {
                    log.debug("{}: push failed: {}", port, e.toString())
                }
            }
        }
    }

    fun offer(data: ByteArray) {
        pending.trySend(data)
    }

    fun close() {
        pending.close()
    }
}
