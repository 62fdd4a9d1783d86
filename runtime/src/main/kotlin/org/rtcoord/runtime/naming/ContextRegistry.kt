package org.rtcoord.runtime.naming

import java.util.concurrent.locks.ReentrantLock
import kotlin.concurrent.withLock
import org.omg.CORBA.portable.ObjectImpl
import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingIterator
import org.omg.CosNaming.BindingIteratorHelper
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.runtime.RuntimeOrb
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger(ContextRegistry::class.java)

/**
 * The live naming contexts of one naming service and the lock that guards all their bindings. One lock for the whole
 * tree keeps a compound name's walk and its final step atomic; every step is a map access.
 */
internal class ContextRegistry(private val orb: RuntimeOrb) {
    val lock = ReentrantLock()

    /** By object key, in creation order: the root comes first. */
    private val live = LinkedHashMap<String, NamingContextServant>()

    /** The context that `corbaloc:...NameService` names. */
    val root: NamingContextServant = create()

    /** All live contexts, the root first. */
    val contexts: List<NamingContextServant>
        get() = lock.withLock { live.values.toList() }

    /** A new context, active and unbound. */
    fun create(): NamingContextServant = lock.withLock {
        val context = NamingContextServant(this)
        val reference = orb.activate(context)
        context.reference = NamingContextExtHelper.unchecked_narrow(reference)
        live[keyOf(reference)] = context
        log.debug("Created a naming context ({} live)", live.size)
        context
    }

    /** The servant of [target] when it is a live context of this service, null for anything else. */
    fun local(target: org.omg.CORBA.Object): NamingContextServant? = lock.withLock { live[keyOf(target)] }

    /** Forgets [context] and deactivates it, so later calls on its reference raise OBJECT_NOT_EXIST. */
    fun retire(context: NamingContextServant) {
        // Only once: deactivating an inactive servant would first activate it again (implicit activation).
        if (lock.withLock { live.remove(keyOf(context.reference)) } != null) orb.deactivate(context)
    }

    /** A new iterator over [rest], for the bindings that did not fit into a list() reply. */
    fun iterator(rest: List<Binding>): BindingIterator =
        BindingIteratorHelper.narrow(orb.activate(BindingIteratorServant(rest, orb)))

    /** [target] as a stringified IOR, for a snapshot. */
    fun toIor(target: org.omg.CORBA.Object): String = orb.orb.object_to_string(target)

    /** A reference from a stringified IOR in a snapshot. */
    fun fromIor(ior: String): org.omg.CORBA.Object = orb.orb.string_to_object(ior)

    /*
     * The object key tells our own references apart from everyone else's: JacORB's transient keys hold
     * a server id that is unique per ORB, while POA names and object ids repeat from ORB to ORB.
     */
    private fun keyOf(target: org.omg.CORBA.Object): String {
        val delegate = (target as ObjectImpl)._get_delegate() as org.jacorb.orb.Delegate
        return String(delegate.objectKey, Charsets.ISO_8859_1)
    }
}
