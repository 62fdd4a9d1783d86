package org.rtcoord.internal

import java.util.AbstractMap.SimpleImmutableEntry
import java.util.concurrent.ConcurrentHashMap

/**
 * A name-value list read into a map, in the order the list gave it: two arrays, searched in turn. A component's, a
 * port's or a connector's profile carries a few to a few dozen properties (a manager's, its whole configuration, read
 * rarely), and a tree keeps those of every component, port, connector and context it read: ten thousand components kept
 * nine `LinkedHashMap`s each, 3.7 KB of entries, tables and views (bench/README.md).
 */
internal class NameValueMap
private constructor(
    private val names: Array<String>,
    private val valuesInOrder: Array<String>,
) : AbstractMap<String, String>() {
    init {
        require(names.size == valuesInOrder.size) { "${names.size} names for ${valuesInOrder.size} values" }
    }

    override val size: Int
        get() = names.size

    override fun containsKey(key: String): Boolean = names.indexOf(key) >= 0

    override fun get(key: String): String? = names.indexOf(key).takeIf { it >= 0 }?.let { valuesInOrder[it] }

    override val entries: Set<Map.Entry<String, String>>
        get() =
            object : AbstractSet<Map.Entry<String, String>>() {
                override val size: Int
                    get() = names.size

                override fun iterator(): Iterator<Map.Entry<String, String>> =
                    names.indices.asSequence().map { SimpleImmutableEntry(names[it], valuesInOrder[it]) }.iterator()
            }

    companion object {
        /** The most lists of names [of] shares: a system has a few kinds of profile, each with its names. */
        private const val SHARED_LISTS = 4096

        /** Lists of names by their names: every component, port or connector of one kind gives the same. */
        private val sharedNames = ConcurrentHashMap<List<String>, Array<String>>()

        /** Lists of values that repeat, by their values: every port of one kind gives the same. */
        private val sharedValues = ConcurrentHashMap<List<String>, Array<String>>()

        /**
         * The map of [names] to [values], each at the same index. Its array of names is the one every map of the same
         * names shares, and when [valuesRepeat] (a port's: every component of a kind has the same ports) so is its
         * array of values, while fewer than [SHARED_LISTS] lists of each are.
         */
        fun of(names: List<String>, values: List<String>, valuesRepeat: Boolean = false): NameValueMap =
            NameValueMap(
                sharedNames.share(names),
                if (valuesRepeat) sharedValues.share(values) else values.toTypedArray(),
            )

        private fun ConcurrentHashMap<List<String>, Array<String>>.share(strings: List<String>): Array<String> =
            get(strings)
                ?: strings.toTypedArray().let { array ->
                    if (size < SHARED_LISTS) putIfAbsent(array.asList(), array) ?: array else array
                }
    }
}
