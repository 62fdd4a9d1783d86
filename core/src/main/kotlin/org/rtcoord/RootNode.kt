package org.rtcoord

import org.rtcoord.internal.TreeCore

/** The root of the tree; its children are the name servers. */
public class RootNode internal constructor(core: TreeCore, private val servers: () -> List<NameServerNode>) :
    DirectoryNode(RtcPath.ROOT, core) {
    override val kind: NodeKind get() = NodeKind.ROOT

    override suspend fun readChildren(previous: List<Node>): List<Node> = servers()
}
