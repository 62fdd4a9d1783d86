package org.rtcoord.runtime.naming

import kotlin.concurrent.withLock
import org.omg.CosNaming.BindingType

/**
 * Every context and binding of a [NamingService] at one moment, to start a new one "with its data" (see
 * [NamingService.start]). Immutable; bound objects are kept as stringified IORs, and bindings to the service's own
 * contexts point to the contexts of the new service.
 */
public class NamingSnapshot internal constructor(internal val contexts: List<ContextImage>) {
    override fun toString(): String =
        "NamingSnapshot(${contexts.size} contexts, ${contexts.sumOf { it.bindings.size }} bindings)"
}

/** One context of a [NamingSnapshot]; the root is the first. */
internal class ContextImage(val bindings: List<BindingImage>)

/** One binding of a [ContextImage]. */
internal class BindingImage(val key: NameKey, val type: BindingType, val target: TargetImage)

internal sealed interface TargetImage {
    /** A context of the same service, by its position in [NamingSnapshot.contexts]. */
    data class Context(val index: Int) : TargetImage

    /** Anything else, as a stringified IOR. */
    data class Reference(val ior: String) : TargetImage
}

/** A snapshot of every live context of this registry. */
internal fun ContextRegistry.capture(): NamingSnapshot = lock.withLock {
    val all = contexts
    val index = all.withIndex().associate { (i, context) -> context to i }
    NamingSnapshot(
        all.map { context ->
            ContextImage(
                context.bindings.values.map { bound ->
                    val own = local(bound.target)?.let { index.getValue(it) }
                    val target =
                        if (own != null) TargetImage.Context(own) else TargetImage.Reference(toIor(bound.target))
                    BindingImage(bound.key, bound.type, target)
                }
            )
        }
    )
}

/** Recreates the contexts and bindings of [snapshot] in this (fresh) registry. */
internal fun ContextRegistry.restore(snapshot: NamingSnapshot) = lock.withLock {
    val contexts = listOf(root) + List(snapshot.contexts.size - 1) { create() }
    snapshot.contexts.forEachIndexed { i, image ->
        for (binding in image.bindings) {
            val target =
                when (val target = binding.target) {
                    is TargetImage.Context -> contexts[target.index].reference
                    is TargetImage.Reference -> fromIor(target.ior)
                }
            contexts[i].bindings[binding.key] = Bound(binding.key, binding.type, target)
        }
    }
}
