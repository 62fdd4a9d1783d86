package org.rtcoord.sim

import kotlinx.coroutines.runBlocking
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.SystemProfiles
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** The paper's localisation system as the fixtures run it, saved as `rtcoord profile save` saves it. */
fun savedLocalisation(): RtsProfile =
    NamingService.start().use { naming ->
        Scenarios.localisation(naming.corbaloc).use {
            runBlocking {
                RtcTree(TreeConfig(nameServers = listOf(naming.address))).use { tree -> SystemProfiles(tree).save() }
            }
        }
    }
