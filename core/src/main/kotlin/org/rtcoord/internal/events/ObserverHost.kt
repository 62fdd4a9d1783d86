package org.rtcoord.internal.events

import java.util.UUID
import java.util.concurrent.Executor
import org.omg.PortableServer.POA
import org.omg.PortableServer.Servant
import org.rtcoord.ObserverFlavour
import org.rtcoord.internal.InboundConnections
import org.rtcoord.internal.RandomIdPoa
import org.slf4j.LoggerFactory

/**
 * Hosts the tree's ComponentObserver servants on the tree's ORB, in a POA of their own: object ids are random (16 bytes
 * from a secure generator) so only the component an observer was given to can reach it, and one thread delivers every
 * call, so each component's hints arrive in the order it sent them (a multi-threaded POA reorders oneway calls).
 * Markers wait for what reached the ORB before them ([inbound]; null when the ORB is not the tree's own, and then they
 * wait for nothing) and are sent by [dispatch] when they could not be sent at once.
 */
internal class ObserverHost(
    rootPoa: () -> POA,
    private val inbound: InboundConnections?,
    private val dispatch: Executor,
) {
    private val log = LoggerFactory.getLogger(ObserverHost::class.java)
    private val poa = RandomIdPoa(rootPoa, "rtcoord-observers", singleThread = true)

    /** An observer attached (or about to be) to one component. */
    inner class Observer internal constructor(val flavour: ObserverFlavour, servant: Servant) {
        private val profileUuid = UUID.randomUUID()

        /**
         * The service profile id; the prefix marks observers this library registered. Made when asked for, to attach or
         * detach: kept as text, it weighed 64 bytes more for as long as the component is watched.
         */
        val profileId: String
            get() = PROFILE_PREFIX + profileUuid

        private val served = poa.serve(servant)
        val reference: org.omg.CORBA.Object
            get() = served.reference

        /**
         * Sends [marker] to this observer, through the ORB like any hint, in a kind no component sends (the enum's
         * count, `STATUS_KIND_NUM`), once the ORB has handed on every message that had reached this host by now. One
         * thread takes the observers' calls in the order the ORB handed them on: when the marker comes back, every hint
         * that reached this host before it was sent has been taken too, however late the thread reading that hint's
         * connection ran. [subject] names the component in the log when the marker cannot be sent; then it never comes
         * back.
         */
        fun sendMarker(marker: String, subject: String) {
            val send = Runnable {
                try {
                    when (flavour) {
                        ObserverFlavour.OPENRTM ->
                            OpenRTM.ComponentObserverHelper.unchecked_narrow(reference)
                                .update_status(OpenRTM.StatusKind.STATUS_KIND_NUM, marker)
                        ObserverFlavour.OMG ->
                            RTC.ComponentObserverHelper.unchecked_narrow(reference)
                                .update_status(RTC.StatusKind.STATUS_KIND_NUM, marker)
                    }
                } catch (e: Exception) {
                    log.debug("{}: marker not sent: {}", subject, e.toString())
                }
            }
            val taken = inbound?.allTaken { dispatch.execute(send) } ?: true
            if (taken) send.run()
        }

        fun close() = served.close()
    }

    /** A new observer of [flavour] passing every hint it receives to [receive]. */
    fun observer(flavour: ObserverFlavour, receive: (Hint) -> Unit): Observer {
        val servant =
            when (flavour) {
                ObserverFlavour.OPENRTM ->
                    object : OpenRTM.ComponentObserverPOA() {
                        override fun update_status(kind: OpenRTM.StatusKind, hint: String?) =
                            receive(Hint.openRtm(kind, hint))
                    }
                ObserverFlavour.OMG ->
                    object : RTC.ComponentObserverPOA() {
                        override fun update_status(kind: RTC.StatusKind, hint: String?) = receive(Hint.omg(kind, hint))
                    }
            }
        return Observer(flavour, servant)
    }

    companion object {
        /** Every observer profile id this library registers starts with it, so stale ones can be recognised. */
        const val PROFILE_PREFIX = "rtcoord-observer-"
    }
}
