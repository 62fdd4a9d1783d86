package org.rtcoord.internal.events

import _SDOPackage.Configuration
import org.rtcoord.OperationFailedException
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.removeLeftBehind

/**
 * Removes from the component the observers this library registered (their profile ids carry
 * [ObserverHost.PROFILE_PREFIX]) whose object is gone: a coordinator that crashed or was restarted left them behind. An
 * observer that still answers belongs to a live tree, this one or another, and stays; so does one whose fate a probe
 * cannot tell (it timed out).
 *
 * Only components that list the services added to them show such observers (OpenRTM-aist 1.0, the fixtures); later
 * OpenRTM versions list none, and drop a stale observer themselves at the first heartbeat it fails to take.
 */
internal suspend fun removeStaleObservers(
    core: TreeCore,
    subject: String,
    component: RTC.RTObject,
    configuration: Configuration,
) {
    val profiles =
        try {
            core.remote.call(subject, "get_service_profiles") { component.get_service_profiles() }
        } catch (e: RtcException) {
            return
        }
    core.removeLeftBehind(
        subject,
        "observer",
        profiles.filter { it.id.orEmpty().startsWith(ObserverHost.PROFILE_PREFIX) },
        { it.id },
        { profile -> profile.service },
        "remove_service_profile",
    ) { id ->
        if (!configuration.remove_service_profile(id))
            throw OperationFailedException(subject, "remove_service_profile", "false")
    }
}
