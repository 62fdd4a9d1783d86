package org.rtcoord

import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** The paper's localisation system on an in-process naming service, and a tree looking at it. */
class LocalisationSystem : AutoCloseable {
    val naming: NamingService = NamingService.start()
    val system: RtSystem = Scenarios.localisation(naming.corbaloc)
    val tree: RtcTree = RtcTree(TreeConfig(nameServers = listOf(naming.address)))

    /** `/127.0.0.1:port/<host>.host_cxt` */
    val host: String = "/${naming.address}/${RuntimeProcess.hostContext}"

    fun path(name: String): String = "$host/$name"

    override fun close() {
        tree.close()
        system.close()
        naming.close()
    }
}
