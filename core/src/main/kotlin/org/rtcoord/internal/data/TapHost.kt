package org.rtcoord.internal.data

import org.omg.CORBA.ORB
import org.omg.PortableServer.POA
import org.omg.PortableServer.Servant
import org.rtcoord.internal.RandomIdPoa

/**
 * Serves the tree's tap objects (`OpenRTM::InPortCdr` endpoints and their [TapPort]s) on the tree's ORB, in a POA of
 * their own with random object ids, so only the out-port a tap was connected to can reach it.
 */
internal class TapHost(private val orb: ORB, rootPoa: () -> POA) {
    private val poa = RandomIdPoa(rootPoa, "rtcoord-taps", singleThread = false)

    /** One served object; [ior] is what a connector's `dataport.corba_cdr.inport_ior` carries. */
    inner class Endpoint internal constructor(servant: Servant) {
        private val served = poa.serve(servant)
        val reference: org.omg.CORBA.Object
            get() = served.reference

        val ior: String = orb.object_to_string(served.reference)

        fun close() = served.close()
    }

    fun serve(servant: Servant): Endpoint = Endpoint(servant)
}
