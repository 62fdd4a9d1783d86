package org.rtcoord.runtime.naming

import kotlin.concurrent.withLock
import org.omg.CORBA.BAD_PARAM
import org.omg.CORBA.NO_PERMISSION
import org.omg.CosNaming.BindingIteratorHolder
import org.omg.CosNaming.BindingListHolder
import org.omg.CosNaming.BindingType
import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContext
import org.omg.CosNaming.NamingContextExt
import org.omg.CosNaming.NamingContextExtPOA
import org.omg.CosNaming.NamingContextHelper
import org.omg.CosNaming.NamingContextPackage.AlreadyBound
import org.omg.CosNaming.NamingContextPackage.NotEmpty
import org.omg.CosNaming.NamingContextPackage.NotFound
import org.omg.CosNaming.NamingContextPackage.NotFoundReason
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger(NamingContextServant::class.java)

/** One CosNaming context. Its bindings are guarded by the [registry]'s lock. */
internal class NamingContextServant(private val registry: ContextRegistry) : NamingContextExtPOA() {
    /** This context's reference, set by the registry right after activation. */
    lateinit var reference: NamingContextExt

    /** In binding order, which is also the order list() reports. */
    val bindings = LinkedHashMap<NameKey, Bound>()

    override fun bind(n: Array<NameComponent>?, obj: org.omg.CORBA.Object?): Unit =
        place(n, obj ?: throw BAD_PARAM("cannot bind a nil reference"), BindingType.nobject, replace = false) {
            next,
            rest,
            target ->
            next.bind(rest, target)
        }

    override fun bind_context(n: Array<NameComponent>?, nc: NamingContext?): Unit =
        place(n, nc ?: throw BAD_PARAM("cannot bind a nil context"), BindingType.ncontext, replace = false) {
            next,
            rest,
            target ->
            next.bind_context(rest, target)
        }

    override fun rebind(n: Array<NameComponent>?, obj: org.omg.CORBA.Object?): Unit =
        place(n, obj ?: throw BAD_PARAM("cannot bind a nil reference"), BindingType.nobject, replace = true) {
            next,
            rest,
            target ->
            next.rebind(rest, target)
        }

    override fun rebind_context(n: Array<NameComponent>?, nc: NamingContext?): Unit =
        place(n, nc ?: throw BAD_PARAM("cannot bind a nil context"), BindingType.ncontext, replace = true) {
            next,
            rest,
            target ->
            next.rebind_context(rest, target)
        }

    /**
     * Binds [target] as [type] at [n] (a [replace] replaces what is bound there); a name through a context of another
     * name server is passed on to it by [elsewhere], the same operation there.
     */
    private fun <T : org.omg.CORBA.Object> place(
        n: Array<NameComponent>?,
        target: T,
        type: BindingType,
        replace: Boolean,
        elsewhere: (NamingContext, Array<NameComponent>, T) -> Unit,
    ): Unit =
        inLastContext(
            n,
            { context, key -> if (replace) context.replace(key, type, target) else context.add(key, type, target) },
        ) { next, rest ->
            elsewhere(next, rest, target)
        }

    override fun resolve(n: Array<NameComponent>?): org.omg.CORBA.Object =
        inLastContext(n, { context, key -> context.lookUp(key).target }) { next, rest ->
            next.resolve(rest)
        }

    override fun unbind(n: Array<NameComponent>?) {
        inLastContext(
            n,
            { context, key ->
                context.lookUp(key)
                context.bindings.remove(key)
                log.debug("Unbound {}", key)
            },
        ) { next, rest ->
            next.unbind(rest)
        }
    }

    override fun new_context(): NamingContext = registry.create().reference

    override fun bind_new_context(n: Array<NameComponent>?): NamingContext =
        inLastContext(
            n,
            { context, key ->
                if (key in context.bindings) throw AlreadyBound()
                registry.create().reference.also { context.add(key, BindingType.ncontext, it) }
            },
        ) { next, rest ->
            next.bind_new_context(rest)
        }

    override fun destroy() {
        registry.lock.withLock {
            // corbaloc names the root; without it the service would be unreachable until restarted.
            if (this === registry.root) throw NO_PERMISSION("the root context cannot be destroyed")
            if (bindings.isNotEmpty()) throw NotEmpty()
        }
        registry.retire(this)
        log.debug("Destroyed a naming context")
    }

    override fun list(how_many: Int, bl: BindingListHolder, bi: BindingIteratorHolder) {
        val all = registry.lock.withLock { bindings.values.map { it.toBinding() } }
        val count = minOf(Integer.toUnsignedLong(how_many), all.size.toLong()).toInt()
        bl.value = all.subList(0, count).toTypedArray()
        // A nil iterator tells the caller that everything fitted.
        bi.value = if (count < all.size) registry.iterator(all.subList(count, all.size)) else null
    }

    override fun to_string(n: Array<NameComponent>?): String = StringifiedNames.format(NameKey.validated(n))

    override fun to_name(sn: String?): Array<NameComponent> = StringifiedNames.parse(sn.orEmpty()).toComponents()

    override fun to_url(addr: String?, sn: String?): String = CorbanameUrl.of(addr.orEmpty(), sn.orEmpty())

    override fun resolve_str(sn: String?): org.omg.CORBA.Object = resolve(to_name(sn))

    /**
     * Walks [n] through the contexts of this service and runs [here] on the last component in the context that holds
     * it, all under the lock. When the walk reaches a context served elsewhere it hands that context the rest of the
     * name through [elsewhere], outside the lock.
     */
    private fun <T> inLastContext(
        n: Array<NameComponent>?,
        here: (NamingContextServant, NameKey) -> T,
        elsewhere: (NamingContext, Array<NameComponent>) -> T,
    ): T {
        val name = NameKey.validated(n)
        val (next, rest) =
            registry.lock.withLock {
                var context = this
                for (i in 0 until name.lastIndex) {
                    val bound = context.bindings[name[i]] ?: throw notFound(NotFoundReason.missing_node, name, i)
                    if (bound.type != BindingType.ncontext) throw notFound(NotFoundReason.not_context, name, i)
                    context =
                        registry.local(bound.target) ?: return@withLock bound.target to name.subList(i + 1, name.size)
                }
                return here(context, name.last())
            }
        return elsewhere(NamingContextHelper.unchecked_narrow(next), rest.toComponents())
    }

    private fun lookUp(key: NameKey): Bound =
        bindings[key] ?: throw NotFound(NotFoundReason.missing_node, arrayOf(key.toComponent()))

    private fun add(key: NameKey, type: BindingType, target: org.omg.CORBA.Object) {
        if (key in bindings) throw AlreadyBound()
        bindings[key] = Bound(key, type, target)
        log.debug("Bound {} ({})", key, if (type == BindingType.ncontext) "context" else "object")
    }

    /** rebind and rebind_context replace a binding only of their own type. */
    private fun replace(key: NameKey, type: BindingType, target: org.omg.CORBA.Object) {
        val existing = bindings[key]
        if (existing != null && existing.type != type) {
            val why =
                if (existing.type == BindingType.ncontext) NotFoundReason.not_object else NotFoundReason.not_context
            throw NotFound(why, arrayOf(key.toComponent()))
        }
        bindings[key] = Bound(key, type, target)
        log.debug("Rebound {}", key)
    }
}
