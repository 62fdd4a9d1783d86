package org.rtcoord.internal.events

import _SDOPackage.NameValue
import _SDOPackage.SDOServiceHelper
import _SDOPackage.ServiceProfile
import kotlin.time.Duration
import org.rtcoord.ObserverFlavour
import org.rtcoord.RtcException
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory

/**
 * The tree's observer on one component: attached in a flavour the component advertises, registered through its SDO
 * configuration as a service profile, and removed the same way.
 */
internal class ObserverLink(
    private val core: TreeCore,
    private val host: ObserverHost,
    private val subject: String,
    private val component: ComponentObject,
) {
    private val log = LoggerFactory.getLogger(ObserverLink::class.java)

    /** The attached observer, or null. */
    var observer: ObserverHost.Observer? = null
        private set

    /**
     * Attaches an observer of a flavour listed in [advertised] (the component's
     * `sdo.service.consumer.available_services`; either flavour when it lists none) that passes its hints to [receive],
     * sends heartbeats every [heartbeat] and data traffic hints at most every [traffic] per port; says how that went.
     * Stale observers a crashed tree left behind are removed first.
     */
    suspend fun attach(
        advertised: String?,
        heartbeat: Duration,
        traffic: Duration,
        receive: (Hint) -> Unit,
    ): Attachment {
        val offered = advertised?.split(',')?.map { it.trim() }?.filter { it.isNotEmpty() }
        // The OpenRTM flavour first, even for an FSM component, whose FSM_STATUS only the FSM4RTC one
        // carries: attached where both are offered, that one breaks OpenRTM-aist-Python 2.1's FSM at its
        // first transition (its post-action listeners take one argument and are called with two) and
        // crashes C++ 2.0.2's rtcd2 built with both (the library and the module define one class twice).
        val flavours = ObserverFlavour.values().filter { offered == null || it.repositoryId in offered }
        if (flavours.isEmpty()) return Attachment.NotOffered(offered.orEmpty())
        val configuration =
            try {
                core.remote.call(subject, "get_configuration") { component.ref.get_configuration() }
            } catch (e: RtcException) {
                return Attachment.Failed("get_configuration: ${e.reason}")
            }
        removeStaleObservers(core, subject, component.ref, configuration)
        val seconds = (heartbeat.inWholeMilliseconds / 1000.0).toString()
        val trafficSeconds = (traffic.inWholeMilliseconds / 1000.0).toString()
        val properties =
            mapOf(
                    "observed_status" to "ALL",
                    "heartbeat.enable" to "YES",
                    "heartbeat.interval" to seconds,
                    "rtc_heartbeat.enable" to "YES",
                    "rtc_heartbeat.interval" to seconds,
                    "port_profile.send_event.min_interval" to trafficSeconds,
                    "port_profile.receive_event.min_interval" to trafficSeconds,
                )
                .map { (name, value) -> NameValue(name, core.orb.orb.create_any().apply { insert_string(value) }) }
                .toTypedArray()
        var failure: String? = null
        for (flavour in flavours) {
            val candidate = host.observer(flavour, receive)
            val profile =
                ServiceProfile(
                    candidate.profileId,
                    flavour.repositoryId,
                    properties,
                    SDOServiceHelper.unchecked_narrow(candidate.reference),
                )
            val accepted =
                try {
                    core.remote.call(subject, "add_service_profile") { configuration.add_service_profile(profile) }
                } catch (e: RtcException) {
                    failure = failure ?: "add_service_profile (${flavour.label}): ${e.reason}"
                    false
                }
            if (accepted) {
                observer = candidate
                return Attachment.Attached(flavour)
            }
            candidate.close()
        }
        return failure?.let(Attachment::Failed) ?: Attachment.Refused(flavours)
    }

    /** Removes the observer from the component, if one is attached; a component that cannot be asked keeps it. */
    suspend fun detach() {
        val attached = observer ?: return
        observer = null
        try {
            val configuration = core.remote.call(subject, "get_configuration") { component.ref.get_configuration() }
            core.remote.call(subject, "remove_service_profile") {
                configuration.remove_service_profile(attached.profileId)
            }
        } catch (e: RtcException) {
            log.debug("{}: could not detach observer: {}", subject, e.message)
        } finally {
            attached.close()
        }
    }

    /**
     * Sends [marker] through the attached observer (see [ObserverHost.Observer.sendMarker]); one that cannot be sent
     * never comes back, and what waits for it waits for its limit.
     */
    fun sendMarker(marker: String) {
        observer?.sendMarker(marker, subject)
    }

    /** Forgets the observer without asking the component: it is gone, and the observer with it. */
    fun drop() {
        observer?.close()
        observer = null
    }
}
