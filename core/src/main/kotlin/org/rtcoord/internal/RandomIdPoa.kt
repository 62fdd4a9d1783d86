package org.rtcoord.internal

import java.security.SecureRandom
import java.util.UUID
import org.omg.CORBA.ORB
import org.omg.CORBA.Policy
import org.omg.PortableServer.IdAssignmentPolicyValue
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper
import org.omg.PortableServer.Servant
import org.omg.PortableServer.ThreadPolicyValue

/**
 * A POA of the tree's ORB, created on first use, whose objects get random ids (16 bytes from a secure generator), so
 * only whoever was handed a reference can reach its object. [singleThread] makes one thread deliver every call, in the
 * order they came (a multi-threaded POA reorders oneway calls).
 */
internal class RandomIdPoa(private val orb: ORB, private val name: String, private val singleThread: Boolean) {
    private val random = SecureRandom()

    private val poa: POA by lazy {
        val root = POAHelper.narrow(orb.resolve_initial_references("RootPOA"))
        root.the_POAManager().activate()
        val policies =
            listOfNotNull(
                root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID),
                if (singleThread) root.create_thread_policy(ThreadPolicyValue.SINGLE_THREAD_MODEL) else null,
            )
        root.create_POA("$name-${UUID.randomUUID()}", root.the_POAManager(), policies.toTypedArray<Policy>())
    }

    /** One served object, until [close]. */
    inner class Served internal constructor(servant: Servant) {
        private val objectId = ByteArray(16).also(random::nextBytes).also { poa.activate_object_with_id(it, servant) }
        private val type = servant._all_interfaces(poa, objectId).first()

        /**
         * A reference to the object, made anew at each call and kept by nobody else: JacORB's reference weighs about a
         * kilobyte, `id_to_reference` keeps the one it makes for as long as the POA lives, and a tree serving an
         * observer for each of ten thousand components needs one only to register it and to send a marker.
         */
        val reference: org.omg.CORBA.Object
            get() = poa.create_reference_with_id(objectId, type)

        fun close() {
            runCatching { poa.deactivate_object(objectId) }
        }
    }

    fun serve(servant: Servant): Served = Served(servant)
}
