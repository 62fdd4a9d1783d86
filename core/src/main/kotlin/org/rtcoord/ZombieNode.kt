package org.rtcoord

import org.rtcoord.internal.TreeCore

/**
 * A registration whose object is dead, unreachable or hung: it is still bound in naming (rtshell marks it with `*`).
 * [cause] says what happened when it was last tried. Below the root, a name server that could not be listed, for
 * whatever reason: unreachable or hung, or something other than a name server answering at its address (a
 * [WrongKindException] saying what answers).
 */
public sealed class ZombieNode(
    path: RtcPath,
    core: TreeCore,
    /** Why the object is taken for dead. */
    public val cause: RtcException,
    private val parent: DirectoryNode,
) : Node(path, core) {
    override val kind: NodeKind
        get() = NodeKind.ZOMBIE

    @JvmSynthetic
    override suspend fun refresh(depth: Int) {
        parent.refresh(0)
    }

    /** Removes the dead binding from its naming context, as `rtdel` does. */
    @JvmSynthetic
    public suspend fun unbind() {
        val context =
            parent as? NamingDirectory
                ?: throw WrongKindException(path.toString(), "binding in a naming context", "object below a manager")
        context.unbind(name)
    }
}

/** The [ZombieNode]s the tree makes ([Node] says why that class is sealed). */
internal class ZombieNodeImpl(path: RtcPath, core: TreeCore, cause: RtcException, parent: DirectoryNode) :
    ZombieNode(path, core, cause, parent)
