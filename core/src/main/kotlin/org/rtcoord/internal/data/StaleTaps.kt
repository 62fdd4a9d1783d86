package org.rtcoord.internal.data

import RTC.PortService
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.isGone
import org.rtcoord.internal.toMap
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger(DataTap::class.java)

/**
 * Removes from [port] the tap connectors of trees that are gone (a coordinator that crashed or was
 * restarted): connectors whose id starts with [DataTap.PREFIX] and whose endpoint no longer answers.
 * A tap whose endpoint answers belongs to a live tree and stays; so does one a probe cannot judge.
 */
internal suspend fun removeStaleTaps(core: TreeCore, subject: String, port: PortService) {
    val profiles = try {
        core.remote.call(subject, "get_connector_profiles") { port.get_connector_profiles() }
    } catch (e: RtcException) {
        return
    }
    for (profile in profiles.filter { it.connector_id.orEmpty().startsWith(DataTap.PREFIX) }) {
        val ior = profile.properties.toMap()["dataport.corba_cdr.inport_ior"]
        val gone = try {
            core.remote.call(subject, "probe tap ${profile.connector_id}") { ior == null || isGone(core.orb.orb.string_to_object(ior)) }
        } catch (e: RtcException) {
            false
        }
        if (!gone) continue
        try {
            core.remote.call(subject, "disconnect") { port.disconnect(profile.connector_id) }
            log.info("{}: removed stale data tap {} left by an earlier run", subject, profile.connector_id)
        } catch (e: RtcException) {
            log.debug("{}: could not remove stale data tap {}: {}", subject, profile.connector_id, e.message)
        }
    }
}
