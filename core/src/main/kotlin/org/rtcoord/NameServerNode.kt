package org.rtcoord

import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContext
import org.omg.CosNaming.NamingContextHelper
import org.rtcoord.internal.NameServerProbe
import org.rtcoord.internal.TreeCore

/** A name server: its root naming context, at `corbaloc:iiop:host:port/NameService`. */
public sealed class NameServerNode(path: RtcPath, core: TreeCore) : NamingDirectory(path, core) {
    override val kind: NodeKind
        get() = NodeKind.NAME_SERVER

    /** `host:port`. */
    public val address: String
        get() = path.nameServer!!

    /** The root context's `corbaloc:` address. */
    public val corbaloc: String
        get() = "corbaloc:iiop:$address/NameService"

    private val root: NamingContext by lazy {
        NamingContextHelper.unchecked_narrow(core.orb.orb.string_to_object(corbaloc))
    }

    @get:JvmSynthetic override val fullName: Array<NameComponent> = emptyArray()

    @JvmSynthetic override fun root(): NamingContext = root

    @JvmSynthetic override suspend fun context(): NamingContext = root

    /** A listing that fails because something other than a name server answers says what answers. */
    @JvmSynthetic
    override suspend fun readChildren(previous: List<Node>, kept: (Node) -> Boolean): List<Node> =
        try {
            super.readChildren(previous, kept)
        } catch (e: RtcException) {
            throw NameServerProbe(core, path, address).explain(e)
        }
}

/** The [NameServerNode]s the tree makes ([Node] says why that class is sealed). */
internal class NameServerNodeImpl(path: RtcPath, core: TreeCore) : NameServerNode(path, core)
