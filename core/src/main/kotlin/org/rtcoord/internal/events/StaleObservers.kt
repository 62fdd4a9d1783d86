package org.rtcoord.internal.events

import _SDOPackage.Configuration
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.isGone
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger(ComponentMonitor::class.java)

/**
 * Removes from the component the observers this library registered (their profile ids carry
 * [ObserverHost.PROFILE_PREFIX]) whose object is gone: a coordinator that crashed or was restarted
 * left them behind. An observer that still answers belongs to a live tree, this one or another, and
 * stays; so does one whose fate a probe cannot tell (it timed out).
 *
 * Only components that list the services added to them show such observers (OpenRTM-aist 1.0, the
 * fixtures); later OpenRTM versions list none, and drop a stale observer themselves at the first
 * heartbeat it fails to take.
 */
internal suspend fun removeStaleObservers(core: TreeCore, subject: String, component: RTC.RTObject, configuration: Configuration) {
    val profiles = try {
        core.remote.call(subject, "get_service_profiles") { component.get_service_profiles() }
    } catch (e: RtcException) {
        return
    }
    for (profile in profiles.filter { it.id.orEmpty().startsWith(ObserverHost.PROFILE_PREFIX) }) {
        val gone = try {
            core.remote.call(subject, "probe observer ${profile.id}") { profile.service == null || isGone(profile.service) }
        } catch (e: RtcException) {
            false
        }
        if (!gone) continue
        try {
            core.remote.call(subject, "remove_service_profile") { configuration.remove_service_profile(profile.id) }
            log.info("{}: removed stale observer {} left by an earlier run", subject, profile.id)
        } catch (e: RtcException) {
            log.debug("{}: could not remove stale observer {}: {}", subject, profile.id, e.message)
        }
    }
}
