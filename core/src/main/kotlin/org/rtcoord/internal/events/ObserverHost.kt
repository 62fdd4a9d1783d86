package org.rtcoord.internal.events

import org.omg.CORBA.ORB
import org.omg.CORBA.Policy
import org.omg.PortableServer.IdAssignmentPolicyValue
import org.omg.PortableServer.POA
import org.omg.PortableServer.POAHelper
import org.omg.PortableServer.Servant
import org.omg.PortableServer.ThreadPolicyValue
import org.rtcoord.ObserverFlavour
import java.security.SecureRandom
import java.util.UUID

/**
 * Hosts the tree's ComponentObserver servants on the tree's ORB, in a POA of their own: object ids are
 * random (16 bytes from a secure generator) so only the component an observer was given to can reach it,
 * and one thread delivers every call, so each component's hints arrive in the order it sent them (a
 * multi-threaded POA reorders oneway calls).
 */
internal class ObserverHost(private val orb: ORB) {
    private val random = SecureRandom()

    private val poa: POA by lazy {
        val root = POAHelper.narrow(orb.resolve_initial_references("RootPOA"))
        root.the_POAManager().activate()
        root.create_POA(
            "rtcoord-observers-${UUID.randomUUID()}",
            root.the_POAManager(),
            arrayOf<Policy>(
                root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID),
                root.create_thread_policy(ThreadPolicyValue.SINGLE_THREAD_MODEL),
            ),
        )
    }

    /** An observer attached (or about to be) to one component. */
    inner class Observer internal constructor(val flavour: ObserverFlavour, private val objectId: ByteArray, servant: Servant) {
        /** The service profile id; the prefix marks observers this library registered. */
        val profileId: String = PROFILE_PREFIX + UUID.randomUUID()
        val reference: org.omg.CORBA.Object = poa.run { activate_object_with_id(objectId, servant); id_to_reference(objectId) }

        fun close() {
            runCatching { poa.deactivate_object(objectId) }
        }
    }

    /** A new observer of [flavour] passing every hint it receives to [receive]. */
    fun observer(flavour: ObserverFlavour, receive: (Hint) -> Unit): Observer {
        val servant = when (flavour) {
            ObserverFlavour.OPENRTM -> object : OpenRTM.ComponentObserverPOA() {
                override fun update_status(kind: OpenRTM.StatusKind, hint: String?) = receive(Hint.openRtm(kind, hint))
            }
            ObserverFlavour.OMG -> object : RTC.ComponentObserverPOA() {
                override fun update_status(kind: RTC.StatusKind, hint: String?) = receive(Hint.omg(kind, hint))
            }
        }
        return Observer(flavour, ByteArray(16).also(random::nextBytes), servant)
    }

    companion object {
        /** Every observer profile id this library registers starts with it, so stale ones can be recognised. */
        const val PROFILE_PREFIX = "rtcoord-observer-"
    }
}
