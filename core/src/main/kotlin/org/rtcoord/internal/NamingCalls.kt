package org.rtcoord.internal

import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingIteratorHolder
import org.omg.CosNaming.BindingListHolder
import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContext
import org.omg.CosNaming.NamingContextHelper
import org.rtcoord.NotFoundException
import org.rtcoord.RtcPath

/**
 * The remote calls a [org.rtcoord.NamingDirectory] makes on its naming [context], found at [path]. A failure to reach
 * the context names the context, not the binding asked about: when the name server goes down mid-listing, it is the
 * server that is unreachable, not the component whose name was next.
 */
internal class NamingCalls(private val core: TreeCore, private val path: RtcPath, private val context: NamingContext) {
    /** Removes the binding [name] (`id.kind`), whatever it is bound to. */
    suspend fun unbind(name: String) {
        try {
            core.remote.call(path.toString(), "unbind $name") { context.unbind(nameComponents(name)) }
        } catch (e: NotFoundException) {
            throw NotFoundException(path.child(name).toString(), "not bound")
        }
    }

    /** What [name] (`id.kind`) is bound to, or null when nothing is. */
    suspend fun resolve(name: String): org.omg.CORBA.Object? = resolve(nameComponents(name))

    /** What the binding [name] is bound to, or null when it was unbound since it was listed. */
    suspend fun resolve(name: Array<NameComponent>): org.omg.CORBA.Object? =
        try {
            core.remote.call(path.toString(), "resolve ${nameOf(name)}") { context.resolve(name) }
        } catch (e: NotFoundException) {
            null
        }

    /** Every binding, fetching past the first batch through the iterator (rtctree stops at 200). */
    suspend fun bindings(): List<Binding> {
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

    companion object {
        const val BATCH = 100

        /** `id.kind` as a CosNaming name; the kind follows the last dot. */
        fun nameComponents(name: String): Array<NameComponent> {
            val dot = name.lastIndexOf('.')
            return arrayOf(
                if (dot < 0) NameComponent(name, "") else NameComponent(name.substring(0, dot), name.substring(dot + 1))
            )
        }

        /** The last component of [name] as `id.kind` (`id` without a kind). */
        fun nameOf(name: Array<NameComponent>): String =
            name.last().let { if (it.kind.isEmpty()) it.id else "${it.id}.${it.kind}" }

        /** The context [fullName] below [root], resolved in one call, as [path]. */
        suspend fun contextAt(
            core: TreeCore,
            path: RtcPath,
            root: NamingContext,
            fullName: Array<NameComponent>,
        ): NamingContext =
            NamingContextHelper.unchecked_narrow(
                core.remote.call(path.toString(), "resolve") { root.resolve(fullName) }
            )
    }
}
