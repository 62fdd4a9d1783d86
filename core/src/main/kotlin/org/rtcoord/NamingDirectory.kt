package org.rtcoord

import OpenRTM.DataFlowComponentHelper
import RTM.ManagerHelper
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingIteratorHolder
import org.omg.CosNaming.BindingListHolder
import org.omg.CosNaming.BindingType
import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContext
import org.rtcoord.internal.TreeCore

/** A naming context in the tree: a name server's root context or a context below it. */
public sealed class NamingDirectory(path: RtcPath, core: TreeCore) : DirectoryNode(path, core) {

    internal abstract suspend fun context(): NamingContext

    /** This context's name from its name server's root context. */
    internal abstract val fullName: Array<NameComponent>

    /** The root context of this context's name server. */
    internal abstract fun root(): NamingContext

    /** Removes the binding [name] (`id.kind`) from this context, whatever it is bound to. */
    public suspend fun unbind(name: String) {
        val context = context()
        core.remote.call(path.child(name).toString(), "unbind") { context.unbind(nameComponents(name)) }
        relist()
    }

    /** Whether [name] (`id.kind`) is bound in this context to [component], alive or not. */
    internal suspend fun binds(name: String, component: org.rtcoord.internal.ComponentObject): Boolean {
        val context = context()
        val target = try {
            core.remote.call(path.child(name).toString(), "resolve") { context.resolve(nameComponents(name)) }
        } catch (e: NotFoundException) {
            return false
        }
        return target._is_equivalent(component.ref)
    }

    override suspend fun readChildren(previous: List<Node>): List<Node> {
        val context = context()
        val bindings = listAll(context)
        return coroutineScope { bindings.map { binding -> async { childFor(context, binding, previous) } }.awaitAll() }.filterNotNull()
    }

    /** Every binding, fetching past the first batch through the iterator (rtctree stops at 200). */
    private suspend fun listAll(context: NamingContext): List<Binding> {
        val subject = path.toString()
        val first = BindingListHolder()
        val rest = BindingIteratorHolder()
        core.remote.call(subject, "list") { context.list(BATCH, first, rest) }
        val bindings = first.value.toMutableList()
        val iterator = rest.value ?: return bindings
        try {
            while (true) {
                val batch = BindingListHolder()
                val more = core.remote.call(subject, "next_n") { iterator.next_n(BATCH, batch) }
                bindings += batch.value
                if (!more || batch.value.isEmpty()) break
            }
        } finally {
            runCatching { core.remote.call(subject, "destroy iterator") { iterator.destroy() } }
        }
        return bindings
    }

    /** The node for [binding], or null if it was unbound since the listing. */
    private suspend fun childFor(context: NamingContext, binding: Binding, previous: List<Node>): Node? {
        val name = binding.binding_name.last().let { if (it.kind.isEmpty()) it.id else "${it.id}.${it.kind}" }
        val childPath = path.child(name)
        val old = previous.firstOrNull { it.name == name }
        if (binding.binding_type == BindingType.ncontext) {
            return old as? ContextNode ?: ContextNode(childPath, core, this, binding.binding_name)
        }
        val target = try {
            core.remote.call(childPath.toString(), "resolve") { context.resolve(binding.binding_name) }
        } catch (e: NotFoundException) {
            return null
        }
        return when (childPath.kind) {
            "rtc" -> {
                val component = core.components.objectFor(DataFlowComponentHelper.unchecked_narrow(target))
                (old as? ComponentNode)?.takeIf { it.component === component } ?: ComponentNode(childPath, core, component, this)
            }
            "mgr" -> (old as? ManagerNode)?.takeIf { it.ref._is_equivalent(target) } ?: ManagerNode(childPath, core, ManagerHelper.unchecked_narrow(target), this)
            else -> UnknownNode(childPath, core, target)
        }
    }

    internal companion object {
        const val BATCH = 100

        /** `id.kind` as a CosNaming name; the kind follows the last dot. */
        fun nameComponents(name: String): Array<NameComponent> {
            val dot = name.lastIndexOf('.')
            return arrayOf(if (dot < 0) NameComponent(name, "") else NameComponent(name.substring(0, dot), name.substring(dot + 1)))
        }
    }
}

/** A naming context below a name server's root. */
public class ContextNode internal constructor(
    path: RtcPath,
    core: TreeCore,
    private val parent: NamingDirectory,
    binding: Array<NameComponent>,
) : NamingDirectory(path, core) {
    override val kind: NodeKind get() = NodeKind.CONTEXT

    override val fullName: Array<NameComponent> = parent.fullName + binding

    override fun root(): NamingContext = parent.root()

    /**
     * Resolved on every use: a restarted name server may serve the context under a new reference. One
     * call from the root with the whole name, not one per level.
     */
    override suspend fun context(): NamingContext {
        val root = parent.root()
        return org.omg.CosNaming.NamingContextHelper.unchecked_narrow(core.remote.call(path.toString(), "resolve") { root.resolve(fullName) })
    }
}
