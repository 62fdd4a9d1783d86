package org.rtcoord

import org.rtcoord.internal.TreeCore

/** A bound object that is neither a component nor a manager (its binding's kind is [bindingKind]). */
public sealed class UnknownNode(
    path: RtcPath,
    core: TreeCore,
    /** The reference bound at [path]. */
    public val reference: org.omg.CORBA.Object,
) : Node(path, core) {
    override val kind: NodeKind
        get() = NodeKind.UNKNOWN

    /** The kind part of the binding name (`rtc`, `mgr`, anything else). */
    public val bindingKind: String
        get() = path.kind

    @JvmSynthetic override suspend fun refresh(depth: Int): Unit = Unit
}

/** The [UnknownNode]s the tree makes ([Node] says why that class is sealed). */
internal class UnknownNodeImpl(path: RtcPath, core: TreeCore, reference: org.omg.CORBA.Object) :
    UnknownNode(path, core, reference)
