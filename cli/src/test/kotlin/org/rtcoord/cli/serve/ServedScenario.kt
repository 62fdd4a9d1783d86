package org.rtcoord.cli.serve

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.naming.NamingService

/**
 * Runs [block] on the system [scenario] builds on a fresh naming service (given its corbaloc), read by a tree, served
 * as the live view and opened in headless Chromium; everything is closed afterwards.
 */
internal fun servedScenario(
    scenario: (String) -> RtSystem,
    block: (tree: RtcTree, service: LiveService, browser: HeadlessChromium) -> Unit,
) {
    NamingService.start().use { naming ->
        scenario(naming.corbaloc).use {
            RtcTree(TreeConfig(listOf(naming.address), 10.seconds)).use { tree ->
                val service = runBlocking {
                    LiveService.start(tree, tree.node("/${naming.address}"), null, EventOptions(), ServeSettings()) {}
                }
                service.use { HeadlessChromium.start().use { browser -> block(tree, service, browser) } }
            }
        }
    }
}
