package org.rtcoord.runtime

import OpenRTM.PortStatus
import OpenRTM.PortStatusHelper
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.InvokeHandler
import org.omg.CORBA.portable.ObjectImpl
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.omg.Messaging.ExceptionHolder
import org.omg.Messaging.ReplyHandler
import org.omg.PortableServer.POA
import org.omg.PortableServer.Servant
import org.slf4j.LoggerFactory

/**
 * Where the replies to one [Publisher]'s `put`s go (CORBA AMI): JacORB hands each to this servant on the thread that
 * read it from the connection, and [replied] gets the status the peer answered, or null when it raised an exception
 * (logged here). Never throws: a reply handler that throws makes JacORB close the connection.
 */
internal class PutReplies(private val port: String, private val replied: (PortStatus?) -> Unit) :
    Servant(), InvokeHandler {
    private val log = LoggerFactory.getLogger(PutReplies::class.java)

    override fun _all_interfaces(poa: POA?, objectId: ByteArray?): Array<String> = arrayOf(REPLY_HANDLER)

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler?): OutputStream? {
        val status =
            try {
                // An exception comes as `put_excep`, holding an ExceptionHolder valuetype.
                if (method == "put") PortStatusHelper.read(input)
                else {
                    log.debug("{}: push failed: {}", port, raised(input).toString())
                    null
                }
            } catch (e: Exception) {
                log.debug("{}: unreadable reply to a push: {}", port, e.toString())
                null
            }
        try {
            replied(status)
        } catch (e: Exception) {
            log.warn("{}: a reply to a push was not handled: {}", port, e.toString())
        }
        return null
    }

    /** A reference to a [PutReplies] served by the ORB, as JacORB takes a reply handler: a `ReplyHandler`. */
    class Reference(served: org.omg.CORBA.Object) : ObjectImpl(), ReplyHandler {
        init {
            _set_delegate((served as ObjectImpl)._get_delegate())
        }

        override fun _ids(): Array<String> = arrayOf(REPLY_HANDLER)
    }

    private companion object {
        const val REPLY_HANDLER = "IDL:omg.org/Messaging/ReplyHandler:1.0"

        /** The exception an exception reply holds. */
        fun raised(input: InputStream): Exception {
            val holder = (input as org.omg.CORBA_2_3.portable.InputStream).read_value() as ExceptionHolder
            return try {
                holder.raise_exception()
                org.omg.CORBA.UNKNOWN("an exception reply without an exception")
            } catch (e: Exception) {
                e
            }
        }
    }
}
