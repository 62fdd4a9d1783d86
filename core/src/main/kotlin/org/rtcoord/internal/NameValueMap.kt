package org.rtcoord.internal

import java.util.AbstractMap.SimpleImmutableEntry

/**
 * A name-value list read into a map, in the order the list gave it: two arrays, searched in turn. A component's, a
 * port's or a connector's profile carries a few to a few dozen properties (a manager's, its whole configuration, read
 * rarely), and a tree keeps those of every component, port, connector and context it read: ten thousand components kept
 * nine `LinkedHashMap`s each, 3.7 KB of entries, tables and views (bench/README.md).
 */
internal class NameValueMap(private val names: Array<String>, private val valuesInOrder: Array<String>) :
    AbstractMap<String, String>() {
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
}
