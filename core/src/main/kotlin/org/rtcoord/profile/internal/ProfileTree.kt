package org.rtcoord.profile.internal

import org.rtcoord.profile.Extension

/**
 * One element of a profile as its format holds it, XML or YAML, named by the YAML form's keys (the XML form names its
 * elements with the first letter capitalised). Each field is taken at most once, so that [ext], called last, keeps what
 * nothing took: a profile read and written again loses nothing.
 */
internal interface ProfileTree {
    /** The single value [key] holds, null when absent. */
    fun text(key: String): String?

    /** The one element [key] holds, null when absent. */
    fun child(key: String): ProfileTree?

    /** The elements [key] holds, in order; empty when absent. */
    fun list(key: String): List<ProfileTree>

    /** A date as the format writes it, as text; empty when absent. */
    fun date(key: String): String

    /** The tool data (comment, visibility, location, properties) and everything not taken; call it last. */
    fun ext(): Extension

    /** Fails: this element has no value [key]. */
    fun missing(key: String): Nothing

    /** Fails: this element has no element [key]. */
    fun missingChild(key: String): Nothing

    /** Fails: [key]'s [value] is not [wanted] ("an integer"). */
    fun invalid(key: String, value: String, wanted: String): Nothing
}

internal fun ProfileTree.requiredText(key: String): String = text(key) ?: missing(key)

internal fun ProfileTree.required(key: String): ProfileTree = child(key) ?: missingChild(key)

internal fun ProfileTree.int(key: String): Int? =
    text(key)?.let { it.trim().toIntOrNull() ?: invalid(key, it, "an integer") }

internal fun ProfileTree.double(key: String): Double? =
    text(key)?.let { it.trim().toDoubleOrNull() ?: invalid(key, it, "a number") }

internal fun ProfileTree.boolean(key: String): Boolean? = text(key)?.let { booleanOf(key, it) }

/** [value], held by [key], as true or false, in any case. */
internal fun ProfileTree.booleanOf(key: String, value: String): Boolean =
    when (value.trim().lowercase()) {
        "true" -> true
        "false" -> false
        else -> invalid(key, value, "true or false")
    }
