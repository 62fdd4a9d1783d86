package org.rtcoord.runtime

import OpenRTM.CdrDataHelper
import OpenRTM.InPortCdr
import OpenRTM.PortStatus
import kotlinx.coroutines.launch
import org.omg.CORBA.SystemException
import org.omg.CORBA.portable.ObjectImpl
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.RemarshalException
import org.slf4j.LoggerFactory

/**
 * Sends an out-port's samples, encoded in its connector's byte order, to one connected in-port, keeping only the newest
 * sample when the peer is slower than the writer (OpenRTM's `new` push policy). A slow or dead peer never blocks the
 * writing component.
 *
 * Each `put` is sent without a thread waiting for its reply (CORBA AMI, as JacORB offers it): the request leaves from
 * the writer's thread and the reply comes to [PutReplies] on the thread that reads the connection. A sample thus costs
 * no hand-over between threads and wakes no thread but that reader: handing each sample to a coroutine that made a
 * blocking call cost four wake-ups per sample, most of what a simulated port at 100 Hz spent (bench/README.md).
 *
 * One put is awaited at a time. A sample written meanwhile is kept (the newest only) and sent from the component's
 * scope when the reply comes. The writer's thread sends only to a peer that answered its last put: the first put, and
 * any after one that failed or went unanswered for the ORB's call deadline, leave from the scope, so connecting, or
 * writing to a peer that stopped reading, never holds the writer.
 *
 * |state                |a sample is written                    |the reply comes                                                         |the deadline has passed at a write                        |
 * |---------------------|---------------------------------------|------------------------------------------------------------------------|----------------------------------------------------------|
 * |idle, peer answering |sent from the writer's thread: awaiting|-                                                                       |-                                                         |
 * |idle, peer not proven|sent from the scope: awaiting          |-                                                                       |-                                                         |
 * |awaiting             |kept, replacing the one kept           |kept one sent from the scope (still awaiting), else idle; peer answering|given up (peer not proven), the sample sent from the scope|
 */
internal class Publisher(
    private val target: InPortCdr,
    private val component: RuntimeComponent,
    private val port: String,
    /** The byte order the connector negotiated (`dataport.serializer.cdr.endian`). */
    val littleEndian: Boolean,
) {
    private val log = LoggerFactory.getLogger(Publisher::class.java)
    private val replies = PutReplies(port, ::finished)
    private val replyHandler = PutReplies.Reference(component.orb.activate(replies))
    private val deadline = component.orb.callTimeout

    private val lock = Any()
    // Guarded by lock.
    private var awaiting = false
    private var sentAt = 0L
    private var kept: ByteArray? = null
    private var answering = false
    private var closed = false

    fun offer(data: ByteArray) {
        val fromWriter =
            synchronized(lock) {
                if (closed) return
                val now = System.nanoTime()
                if (awaiting) {
                    if (now - sentAt < deadline.inWholeNanoseconds) {
                        kept = data
                        return
                    }
                    log.debug("{}: no reply to a put within {}", port, deadline)
                    answering = false
                }
                awaiting = true
                sentAt = now
                answering
            }
        if (fromWriter) send(data) else component.scope.launch { send(data) }
    }

    /**
     * Sends nothing more; the reply handler leaves the ORB once no put is awaited (a reply that never comes keeps it).
     */
    fun close() {
        val idle =
            synchronized(lock) {
                closed = true
                kept = null
                !awaiting
            }
        if (idle) component.orb.deactivate(replies)
    }

    private fun send(data: ByteArray) {
        val stub = target as ObjectImpl
        while (true) {
            var request: OutputStream? = null
            try {
                request = stub._request("put", true)
                CdrDataHelper.write(request, data)
                (stub._get_delegate() as org.jacorb.orb.Delegate).invoke(stub, request, replyHandler)
                return
            } catch (e: RemarshalException) {
                // The connection changed under the request: it is made again, as a stub does.
            } catch (e: SystemException) {
                log.debug("{}: push failed: {}", port, e.toString())
                return finished(null)
            } finally {
                // Written out already: its buffer goes back to JacORB's pool rather than to the garbage collector.
                request?.close()
            }
        }
    }

    /**
     * The awaited put is over: the peer answered [status], or null when the put failed, to send or in its reply (the
     * connection lost, the in-port gone): such a peer is not trusted with the writer's thread. Runs on the connection's
     * reader thread for a reply, which must not send (it would wait for itself) nor throw (JacORB would close the
     * connection).
     */
    private fun finished(status: PortStatus?) {
        if (status != null && status != PortStatus.PORT_OK) log.debug("{}: peer answered {}", port, status.value())
        var leave = false
        val next =
            synchronized(lock) {
                answering = status != null
                kept.also {
                    kept = null
                    if (it == null) {
                        awaiting = false
                        leave = closed
                    } else sentAt = System.nanoTime()
                }
            }
        if (next != null) component.scope.launch { send(next) }
        if (leave) component.scope.launch { component.orb.deactivate(replies) }
    }
}
