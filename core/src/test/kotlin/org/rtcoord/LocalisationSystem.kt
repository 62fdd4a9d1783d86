package org.rtcoord

import org.rtcoord.fixtures.FixtureRuntime
import org.rtcoord.fixtures.RtSystem
import org.rtcoord.fixtures.Scenarios
import org.rtcoord.fixtures.naming.NamingService

/** The paper's localisation system on an in-process naming service, and a tree looking at it. */
class LocalisationSystem : AutoCloseable {
    val naming: NamingService = NamingService.start()
    val system: RtSystem = Scenarios.localisation(naming.corbaloc)
    val tree: RtcTree = RtcTree.create(TreeConfig(nameServers = listOf(naming.address)))

    /** `/127.0.0.1:port/<host>.host_cxt` */
    val host: String = "/${naming.address}/${FixtureRuntime.hostContext}"

    fun path(name: String): String = "$host/$name"

    override fun close() {
        tree.close()
        system.close()
        naming.close()
    }
}
