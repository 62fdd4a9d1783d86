package org.rtcoord.internal.data

import org.omg.CORBA.ORB
import org.omg.CORBA.Policy
import org.omg.PortableServer.IdAssignmentPolicyValue
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper
import org.omg.PortableServer.Servant
import java.security.SecureRandom
import java.util.UUID

/**
 * Serves the tree's tap endpoints (`OpenRTM::InPortCdr` servants) on the tree's ORB, in a POA of their
 * own with random object ids, so only the out-port a tap was connected to can reach it.
 */
internal class TapHost(private val orb: ORB) {
    private val random = SecureRandom()

    private val poa: POA by lazy {
        val root = POAHelper.narrow(orb.resolve_initial_references("RootPOA"))
        root.the_POAManager().activate()
        root.create_POA(
            "rtcoord-taps-${UUID.randomUUID()}",
            root.the_POAManager(),
            arrayOf<Policy>(root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID)),
        )
    }

    /** One served object; [ior] is what a connector's `dataport.corba_cdr.inport_ior` carries. */
    inner class Endpoint internal constructor(servant: Servant) {
        private val objectId = ByteArray(16).also(random::nextBytes)
        val reference: org.omg.CORBA.Object = poa.run {
            activate_object_with_id(objectId, servant)
            id_to_reference(objectId)
        }
        val ior: String = orb.object_to_string(reference)

        fun close() {
            runCatching { poa.deactivate_object(objectId) }
        }
    }

    fun serve(servant: Servant): Endpoint = Endpoint(servant)
}
