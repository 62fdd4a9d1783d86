package org.rtcoord.internal

/**
 * A value per execution context handle, in the order the handles were first put: a component is in one context, rarely
 * more, and a tree watching ten thousand components keeps several of these each, where a `HashMap` of one entry weighs
 * some 150 bytes and these two arrays 50. Not thread-safe: its owner guards it.
 */
internal class HandleMap<V : Any> {
    private var handles = IntArray(0)
    private var values = arrayOfNulls<Any>(0)

    /** How many handles have a value. */
    val size: Int
        get() = handles.size

    /** The value put for [handle], or null. */
    operator fun get(handle: Int): V? = handles.indexOf(handle).takeIf { it >= 0 }?.let(::valueAt)

    /** Puts [value] for [handle], replacing the one it had (which keeps its place). */
    operator fun set(handle: Int, value: V) {
        val index = handles.indexOf(handle)
        if (index >= 0) {
            values[index] = value
        } else {
            handles = handles.copyOf(handles.size + 1).also { it[handles.size] = handle }
            values = values.copyOf(values.size + 1).also { it[values.size] = value }
        }
    }

    /** The value of [handle], put first if it has none. */
    fun getOrPut(handle: Int, make: () -> V): V = get(handle) ?: make().also { set(handle, it) }

    /** The values, in the handles' order. */
    fun values(): List<V> = List(size, ::valueAt)

    /** Calls [action] with each handle and its value, in order. */
    fun forEach(action: (Int, V) -> Unit) {
        for (index in 0 until size) action(handleAt(index), valueAt(index))
    }

    /** Forgets every handle [keep] rejects. */
    fun retain(keep: (Int) -> Boolean) {
        val kept = handles.indices.filter { keep(handles[it]) }
        if (kept.size == handles.size) return
        handles = IntArray(kept.size) { handles[kept[it]] }
        values = Array(kept.size) { values[kept[it]] }
    }

    private fun handleAt(index: Int): Int = handles[index]

    @Suppress("UNCHECKED_CAST") private fun valueAt(index: Int): V = values[index] as V
}
