package org.rtcoord.internal

import java.nio.ByteBuffer
import java.security.SecureRandom
import java.util.UUID
import java.util.concurrent.ConcurrentHashMap
import org.omg.CORBA.LocalObject
import org.omg.CORBA.OBJECT_NOT_EXIST
import org.omg.CORBA.Policy
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.InvokeHandler
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.omg.PortableServer.IdAssignmentPolicyValue
import org.omg.PortableServer.POA
import org.omg.PortableServer.RequestProcessingPolicyValue
import org.omg.PortableServer.Servant
import org.omg.PortableServer.ServantLocator
import org.omg.PortableServer.ServantLocatorPackage.CookieHolder
import org.omg.PortableServer.ServantRetentionPolicyValue
import org.omg.PortableServer.ThreadPolicyValue

/**
 * A POA under the tree's ORB's [rootPoa], created on first use, whose objects get random ids (16 bytes from a secure
 * generator), so only whoever was handed a reference can reach its object. [singleThread] makes one thread deliver
 * every call, in the order they came (a multi-threaded POA reorders oneway calls).
 *
 * The POA keeps no map of its own (`NON_RETAIN`): each call finds its servant in [servants]. A retaining JacORB POA
 * runs a thread of its own for the life of the ORB to take deactivated objects out of its map, and its entries weigh
 * more than one small key per object; a coordinator serves an observer for each component it watches.
 */
internal class RandomIdPoa(
    private val rootPoa: () -> POA,
    private val name: String,
    private val singleThread: Boolean,
) {
    private val random = SecureRandom()
    private val servants = ConcurrentHashMap<ObjectKey, Servant>()

    private val poa: POA by lazy {
        val root = rootPoa()
        root.the_POAManager().activate()
        val policies =
            listOfNotNull(
                root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID),
                root.create_servant_retention_policy(ServantRetentionPolicyValue.NON_RETAIN),
                root.create_request_processing_policy(RequestProcessingPolicyValue.USE_SERVANT_MANAGER),
                if (singleThread) root.create_thread_policy(ThreadPolicyValue.SINGLE_THREAD_MODEL) else null,
            )
        root.create_POA("$name-${UUID.randomUUID()}", root.the_POAManager(), policies.toTypedArray<Policy>()).apply {
            set_servant_manager(Locator())
        }
    }

    /** One served object, until [close]. */
    inner class Served internal constructor(servant: Servant) {
        private val key = ObjectKey(random.nextLong(), random.nextLong()).also { servants[it] = servant }
        private val type = servant._all_interfaces(poa, key.objectId()).first()

        /**
         * A reference to the object, made anew at each call and kept by nobody else: JacORB's reference weighs about a
         * kilobyte, and a tree serving an observer for each of ten thousand components needs one only to register it
         * and to send a marker.
         */
        val reference: org.omg.CORBA.Object
            get() = poa.create_reference_with_id(key.objectId(), type)

        /** Takes the object out of the POA: a call that comes later fails with `OBJECT_NOT_EXIST`. */
        fun close() {
            servants.remove(key)
        }
    }

    fun serve(servant: Servant): Served = Served(servant)

    /** An object id as two numbers: smaller than the id's array and an entry for it in a map keyed by arrays. */
    private data class ObjectKey(val high: Long, val low: Long) {
        fun objectId(): ByteArray = ByteBuffer.allocate(ID_SIZE).putLong(high).putLong(low).array()

        companion object {
            const val ID_SIZE = 16

            fun of(objectId: ByteArray): ObjectKey? =
                if (objectId.size != ID_SIZE) null
                else ByteBuffer.wrap(objectId).let { ObjectKey(it.getLong(), it.getLong()) }
        }
    }

    /**
     * Finds the servant of each call; JacORB calls it on the thread that then runs the call. An id it does not serve
     * gets [Gone] rather than an exception: JacORB 3.9 goes on with the servant a throwing locator left unset, and the
     * thread that took the call dies without telling its POA, which then waits for that call for ever when it is
     * destroyed.
     */
    private inner class Locator : LocalObject(), ServantLocator {
        private val gone = Gone()

        override fun preinvoke(oid: ByteArray, adapter: POA, operation: String, cookie: CookieHolder): Servant =
            ObjectKey.of(oid)?.let(servants::get) ?: gone

        override fun postinvoke(oid: ByteArray, adapter: POA, operation: String, cookie: Any?, servant: Servant?) = Unit
    }

    /** Answers every call to an object no longer served as CORBA says it must: `OBJECT_NOT_EXIST`. */
    private inner class Gone : Servant(), InvokeHandler {
        override fun _all_interfaces(poa: POA?, objectId: ByteArray?): Array<String> = arrayOf(OBJECT_TYPE)

        override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream =
            throw notServed()

        override fun _is_a(repositoryId: String): Boolean = throw notServed()

        override fun _non_existent(): Boolean = true

        private fun notServed() = OBJECT_NOT_EXIST("no object of $name has this id")
    }

    private companion object {
        const val OBJECT_TYPE = "IDL:omg.org/CORBA/Object:1.0"
    }
}
