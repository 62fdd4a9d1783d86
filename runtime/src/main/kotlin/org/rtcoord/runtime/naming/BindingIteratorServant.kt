package org.rtcoord.runtime.naming

import org.omg.CORBA.BAD_PARAM
import org.omg.CosNaming.Binding
import org.omg.CosNaming.BindingHolder
import org.omg.CosNaming.BindingIteratorPOA
import org.omg.CosNaming.BindingListHolder
import org.omg.CosNaming.BindingType
import org.rtcoord.runtime.RuntimeOrb

/** Hands out the bindings a list() reply had no room for; they were copied when list() was called. */
internal class BindingIteratorServant(bindings: List<Binding>, private val orb: RuntimeOrb) : BindingIteratorPOA() {
    private val remaining = ArrayDeque(bindings)

    @Synchronized
    override fun next_one(b: BindingHolder): Boolean {
        val next = remaining.removeFirstOrNull()
        // The out parameter is marshalled even when there is nothing left, so it must not be null.
        b.value = next ?: Binding(emptyArray(), BindingType.nobject)
        return next != null
    }

    @Synchronized
    override fun next_n(how_many: Int, bl: BindingListHolder): Boolean {
        if (how_many == 0) throw BAD_PARAM("next_n(0)")
        val count = minOf(Integer.toUnsignedLong(how_many), remaining.size.toLong()).toInt()
        bl.value = Array(count) { remaining.removeFirst() }
        return count > 0
    }

    override fun destroy() {
        orb.deactivate(this)
    }
}
