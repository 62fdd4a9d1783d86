package org.rtcoord.runtime.naming

import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingType

/** What one name in a context is bound to. */
internal class Bound(val key: NameKey, val type: BindingType, val target: org.omg.CORBA.Object) {
    fun toBinding(): Binding = Binding(arrayOf(key.toComponent()), type)
}
