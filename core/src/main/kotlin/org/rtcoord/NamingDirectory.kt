package org.rtcoord

import OpenRTM.DataFlowComponentHelper
import RTM.ManagerHelper
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingType
import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContext
import org.rtcoord.idl.ObjectIdentity
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.NamingCalls
import org.rtcoord.internal.TreeCore

/** A naming context in the tree: a name server's root context or a context below it. */
public sealed class NamingDirectory(path: RtcPath, core: TreeCore) : DirectoryNode(path, core) {

    @JvmSynthetic internal abstract suspend fun context(): NamingContext

    /** This context's name from its name server's root context. */
    @get:JvmSynthetic internal abstract val fullName: Array<NameComponent>

    /** The root context of this context's name server. */
    @JvmSynthetic internal abstract fun root(): NamingContext

    /** Where its remote calls are made, on the context as resolved now. */
    private suspend fun calls(): NamingCalls = NamingCalls(core, path, context())

    /** Removes the binding [name] (`id.kind`) from this context, whatever it is bound to. */
    @JvmSynthetic
    public suspend fun unbind(name: String) {
        calls().unbind(name)
        relist()
    }

    /** Whether [name] (`id.kind`) is bound in this context to [component], alive or not. */
    @JvmSynthetic
    internal suspend fun binds(name: String, component: ComponentObject): Boolean =
        calls().resolve(name)?.let { ObjectIdentity.same(it, component.ref) } ?: false

    @JvmSynthetic
    override suspend fun readChildren(previous: List<Node>, kept: (Node) -> Boolean): List<Node> {
        val calls = calls()
        val bindings = calls.bindings()
        val before = previous.associateBy { it.name }
        return coroutineScope {
            bindings.map { binding -> async { childFor(calls, binding, before, kept) } }.awaitAll()
        }
            .filterNotNull()
    }

    /**
     * The node for [binding], or null if it was unbound since the listing; [before] are the nodes listed last, and
     * those [kept] accepts stand for their bindings unresolved.
     */
    private suspend fun childFor(
        calls: NamingCalls,
        binding: Binding,
        before: Map<String, Node>,
        kept: (Node) -> Boolean,
    ): Node? {
        val name = NamingCalls.nameOf(binding.binding_name)
        val childPath = path.child(name)
        val old = before[name]
        if (binding.binding_type == BindingType.ncontext) {
            return old as? ContextNode ?: ContextNodeImpl(childPath, core, this, binding.binding_name)
        }
        if (old != null && kept(old)) return old
        val target = calls.resolve(binding.binding_name) ?: return null
        return when (childPath.kind) {
            "rtc" -> {
                val component = core.components.objectFor(DataFlowComponentHelper.unchecked_narrow(target))
                (old as? ComponentNode)?.takeIf { it.component === component }
                    ?: ComponentNodeImpl(childPath, core, component, this)
            }
            "mgr" ->
                (old as? ManagerNode)?.takeIf { ObjectIdentity.same(it.ref, target) }
                    ?: ManagerNodeImpl(childPath, core, ManagerHelper.unchecked_narrow(target), this)
            else -> UnknownNodeImpl(childPath, core, target)
        }
    }
}

/** A naming context below a name server's root. */
public sealed class ContextNode(
    path: RtcPath,
    core: TreeCore,
    private val parent: NamingDirectory,
    binding: Array<NameComponent>,
) : NamingDirectory(path, core) {
    override val kind: NodeKind
        get() = NodeKind.CONTEXT

    @get:JvmSynthetic override val fullName: Array<NameComponent> = parent.fullName + binding

    @JvmSynthetic override fun root(): NamingContext = parent.root()

    /**
     * Resolved on every use: a restarted name server may serve the context under a new reference. One call from the
     * root with the whole name, not one per level.
     */
    @JvmSynthetic
    override suspend fun context(): NamingContext {
        return NamingCalls.contextAt(core, path, parent.root(), fullName)
    }
}

/** The [ContextNode]s the tree makes ([Node] says why that class is sealed). */
internal class ContextNodeImpl(path: RtcPath, core: TreeCore, parent: NamingDirectory, binding: Array<NameComponent>) :
    ContextNode(path, core, parent, binding)
