package org.rtcoord.internal

import RTC.RTObject

/**
 * One [ComponentObject] per component, however many paths reach it (its naming context, its manager, a second name
 * server): references are matched by the ORB's notion of equivalence, with a local hash to keep lookups cheap in large
 * systems.
 */
internal class ComponentRegistry(private val core: TreeCore) {
    private val buckets = HashMap<Int, MutableList<ComponentObject>>()

    fun objectFor(ref: RTObject): ComponentObject =
        synchronized(buckets) {
            val bucket = buckets.getOrPut(ref._hash(Int.MAX_VALUE)) { mutableListOf() }
            bucket.firstOrNull { it.ref._is_equivalent(ref) } ?: ComponentObject(core, ref).also { bucket += it }
        }
}
