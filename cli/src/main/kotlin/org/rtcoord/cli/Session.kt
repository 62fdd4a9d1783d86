package org.rtcoord.cli

import kotlin.time.Duration
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.nameServerPath

/**
 * What the global options decided, shared by the commands of one run. The tree is made on first use, so a command that
 * fails on its arguments never starts an ORB, and closed with the session.
 */
class Session(
    /** Name servers from `-n` or the environment. */
    val nameServers: List<String>,
    /** The deadline of every remote call. */
    val timeout: Duration,
    /** Whether listings print JSON. */
    val json: Boolean,
    /** Whether errors carry their stack trace. */
    val verbose: Boolean,
    /** Whether confirmations and progress are left out. */
    val quiet: Boolean,
    /** The working directory the environment set (`RTCOORD_CWD`, `RTCSH_CWD`), or null. */
    val workingDirectory: RtcPath?,
    /** The one address the ORB listens on, or null for the one that reaches the first name server. */
    val listenAddress: String? = null,
) : AutoCloseable {
    /**
     * Where relative paths start: the [workingDirectory] the environment set, else the first name server given; null
     * when there is neither.
     */
    val start: RtcPath?
        get() = workingDirectory ?: nameServers.firstOrNull()?.let(::nameServerPath)

    private val lazyTree = lazy { RtcTree(treeConfig()) }

    /** A tree's configuration for [servers], with the run's deadline and listen address. */
    fun treeConfig(servers: List<String> = nameServers): TreeConfig =
        TreeConfig(servers, timeout, listenAddress = listenAddress)

    /** The tree over the system, created on first use. */
    val tree: RtcTree by lazyTree

    /** Closes the tree if one was made. */
    override fun close() {
        if (lazyTree.isInitialized()) tree.close()
    }
}
