package org.rtcoord.internal

import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.launch
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.InvokeHandler
import org.omg.CORBA.portable.ObjectImpl
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.omg.Messaging.ExceptionHolder
import org.omg.Messaging.ReplyHandler
import org.omg.PortableServer.POA
import org.omg.PortableServer.Servant

/**
 * Requests sent without a thread waiting for their replies: CORBA's asynchronous method invocation as JacORB implements
 * it, where the connection's reader thread hands each reply to a reply handler of ours as it reads it. A blocking call
 * also wakes the calling thread for every reply; polling 1000 components at 10 Hz, that doubled the CPU of each read
 * (53 against 22 us, bench/README.md).
 *
 * Only a JacORB ORB offers it: [supports] says whether a reference can be reached this way.
 */
internal class AsyncRequests(rootPoa: () -> POA, private val scope: CoroutineScope) {
    private val poa = RandomIdPoa(rootPoa, "rtcoord-replies", singleThread = false)

    /** Whether requests to [target] can be sent through here: it is a JacORB reference. */
    fun supports(target: org.omg.CORBA.Object): Boolean =
        (target as? ObjectImpl)?.let { runCatching { it._get_delegate() }.getOrNull() } is org.jacorb.orb.Delegate

    /**
     * Where the replies to the requests made through it go, on the reader thread of their connection: [received] gets
     * each reply's id and body, positioned at the result; [failed] each exception reply (whose request JacORB does not
     * name). Both must return at once and never throw: a reply handler that throws makes JacORB close the connection,
     * with every call pending on it.
     */
    inner class Replies(
        private val received: (requestId: Int, result: InputStream) -> Unit,
        private val failed: (Exception) -> Unit,
    ) {
        private val outstanding = AtomicInteger()
        @Volatile private var closing = false
        private val served = poa.serve(Handler())
        private val reference = HandlerReference(served.reference)

        /**
         * A request of [operation] to [target], to be completed with its arguments and [Request.send]: its [Request.id]
         * is known before it leaves, so a reply can never arrive before its sender knows which request it answers.
         */
        fun request(target: org.omg.CORBA.Object, operation: String): Request = Request(target as ObjectImpl, operation)

        /**
         * Stops taking replies: the handler leaves the ORB once no reply is outstanding (at once, or when the last one
         * arrives). A reply that never arrives, because its connection was lost, keeps it.
         */
        fun close() {
            closing = true
            if (outstanding.get() == 0) served.close()
        }

        private fun answered() {
            // Not on the reader thread: the ORB is in the middle of delivering to this very handler.
            if (outstanding.decrementAndGet() == 0 && closing) scope.launch { served.close() }
        }

        /** One request, marshalled into [arguments] before it is sent. */
        inner class Request internal constructor(private val target: ObjectImpl, operation: String) {
            val arguments: OutputStream = target._request(operation, true)
            val id: Int = (arguments as org.jacorb.orb.giop.RequestOutputStream).requestId()

            /** Sends it; throws the CORBA exception of a request that could not be sent, whose reply never comes. */
            fun send() {
                outstanding.incrementAndGet()
                try {
                    (target._get_delegate() as org.jacorb.orb.Delegate).invoke(target, arguments, reference)
                } catch (e: Exception) {
                    outstanding.decrementAndGet()
                    throw e
                }
            }
        }

        private inner class Handler : Servant(), InvokeHandler {
            override fun _all_interfaces(poa: POA?, objectId: ByteArray?): Array<String> = arrayOf(REPLY_HANDLER_ID)

            override fun _invoke(method: String, input: InputStream, handler: ResponseHandler?): OutputStream? {
                try {
                    // An exception reply comes as `<operation>_excep` with an ExceptionHolder valuetype.
                    if (method.endsWith(EXCEPTION_SUFFIX)) {
                        failed(exceptionOf(input))
                    } else {
                        received((input as org.jacorb.orb.giop.ReplyInputStream).rep_hdr.request_id, input)
                    }
                } catch (e: Exception) {
                    failed(e)
                } finally {
                    answered()
                }
                return null
            }
        }
    }

    /** The reference JacORB wants for a reply handler: an object of the ReplyHandler interface. */
    private class HandlerReference(served: org.omg.CORBA.Object) : ObjectImpl(), ReplyHandler {
        init {
            _set_delegate((served as ObjectImpl)._get_delegate())
        }

        override fun _ids(): Array<String> = arrayOf(REPLY_HANDLER_ID)
    }

    private companion object {
        const val REPLY_HANDLER_ID = "IDL:omg.org/Messaging/ReplyHandler:1.0"
        const val EXCEPTION_SUFFIX = "_excep"

        fun exceptionOf(input: InputStream): Exception {
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
