package org.rtcoord

import org.rtcoord.internal.TreeCore

/**
 * The root of the tree; its children are the name servers. Every name server the tree has is one of them, whatever
 * answers at its address: one that cannot be listed is a [ZombieNode] whose cause says why (unreachable, hung, or
 * something else answering there), and never fails the others' reads.
 */
public sealed class RootNode(core: TreeCore, private val servers: () -> List<NameServerNode>) :
    DirectoryNode(RtcPath("/"), core) {
    override val kind: NodeKind
        get() = NodeKind.ROOT

    @JvmSynthetic
    override suspend fun readChildren(previous: List<Node>, kept: (Node) -> Boolean): List<Node> = servers()

    /** The name servers as they are now, each as last shown (a server found dead stays a zombie until read again). */
    @JvmSynthetic
    override fun settled(listed: List<Node>): List<Node> =
        servers().map { server -> listed.firstOrNull { it.path == server.path } ?: server }

    @JvmSynthetic override fun buries(failure: RtcException): Boolean = true
}

/** The [RootNode] the tree makes ([Node] says why that class is sealed). */
internal class RootNodeImpl(core: TreeCore, servers: () -> List<NameServerNode>) : RootNode(core, servers)
