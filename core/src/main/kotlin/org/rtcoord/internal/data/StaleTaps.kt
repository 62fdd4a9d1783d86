package org.rtcoord.internal.data

import RTC.PortService
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.orFail
import org.rtcoord.internal.removeLeftBehind
import org.rtcoord.internal.toMap

/**
 * Removes from [port] the tap connectors of trees that are gone (a coordinator that crashed or was restarted):
 * connectors whose id starts with [DataTap.PREFIX] and whose endpoint no longer answers. A tap whose endpoint answers
 * belongs to a live tree and stays; so does one a probe cannot judge.
 */
internal suspend fun removeStaleTaps(core: TreeCore, subject: String, port: PortService) {
    val profiles =
        try {
            core.remote.call(subject, "get_connector_profiles") { port.get_connector_profiles() }
        } catch (e: RtcException) {
            return
        }
    core.removeLeftBehind(
        subject,
        "data tap",
        profiles.filter { it.connector_id.orEmpty().startsWith(DataTap.PREFIX) },
        { it.connector_id },
        { profile -> profile.properties.toMap()["dataport.corba_cdr.inport_ior"]?.let(core.orb.orb::string_to_object) },
        "disconnect",
    ) { id ->
        port.disconnect(id).orFail(subject, "disconnect")
    }
}
