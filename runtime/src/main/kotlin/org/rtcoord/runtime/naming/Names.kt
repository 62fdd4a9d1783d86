package org.rtcoord.runtime.naming

import org.omg.CosNaming.NameComponent
import org.omg.CosNaming.NamingContextPackage.InvalidName
import org.omg.CosNaming.NamingContextPackage.NotFound
import org.omg.CosNaming.NamingContextPackage.NotFoundReason

/** One name component as a map key: bindings are told apart by id and kind together. */
internal data class NameKey(val id: String, val kind: String) {
    fun toComponent(): NameComponent = NameComponent(id, kind)

    companion object {
        /** The keys of [name]; raises InvalidName for an empty name or a component with an empty id. */
        fun validated(name: Array<NameComponent>?): List<NameKey> {
            if (name.isNullOrEmpty()) throw InvalidName()
            return name.map { component ->
                if (component.id.isNullOrEmpty()) throw InvalidName()
                NameKey(component.id, component.kind.orEmpty())
            }
        }
    }
}

internal fun List<NameKey>.toComponents(): Array<NameComponent> = Array(size) { this[it].toComponent() }

/** NotFound for [name] at component [at]; the spec puts the offending component first in rest_of_name. */
internal fun notFound(why: NotFoundReason, name: List<NameKey>, at: Int): NotFound =
    NotFound(why, name.subList(at, name.size).toComponents())
