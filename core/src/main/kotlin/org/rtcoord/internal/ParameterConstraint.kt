package org.rtcoord.internal

/**
 * The constraints OpenRTM components declare for their parameters in the hidden `__constraints__` configuration set, as
 * RT System Editor reads them: a range on `x` (`0<x<10`, `x>=0`, `-1<=x<=1`) or an enumeration (`(slow,fast)`). Other
 * forms (arrays, hashes) are not checked.
 *
 * OpenRTM-aist itself never checks them (neither ConfigAdmin in C++ nor in Python reads the set; only RT System
 * Editor's widgets do), so components hold values outside them, as its own ConfigSample does: a value outside one is a
 * warning, refused only when the caller asks to be strict.
 */
internal object ParameterConstraint {
    /** The hidden configuration set where a component declares its parameters' constraints. */
    const val SET = "__constraints__"

    private val NUMBER = """[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"""
    private val RANGE = Regex("""^\s*(?:($NUMBER)\s*(<=|<|>=|>)\s*)?x\s*(?:(<=|<|>=|>)\s*($NUMBER))?\s*$""")
    private val ENUMERATION = Regex("""^\s*\((.*)\)\s*$""")

    /** Why [value] breaks [constraint], or null when it meets it (or the constraint is of a form not checked). */
    fun violation(constraint: String, value: String): String? {
        ENUMERATION.matchEntire(constraint)?.let { match ->
            val allowed = match.groupValues[1].split(',').map { it.trim() }
            return if (value.trim() in allowed) null else "'$value' is not one of ${constraint.trim()}"
        }
        val range =
            RANGE.matchEntire(constraint)?.takeIf { it.groupValues[1].isNotEmpty() || it.groupValues[3].isNotEmpty() }
                ?: return null
        val x = value.trim().toDoubleOrNull() ?: return "'$value' is not a number (constraint ${constraint.trim()})"
        val (lower, lowerOperator, upperOperator, upper) = range.destructured
        val holds =
            (lower.isEmpty() || compare(lower.toDouble(), lowerOperator, x)) &&
                (upper.isEmpty() || compare(x, upperOperator, upper.toDouble()))
        return if (holds) null else "'$value' is outside ${constraint.trim()}"
    }

    /**
     * The values of [values] that break their parameter's constraint in [constraints], by parameter, with why; a value
     * the set [held] already is left out: what the system holds is never refused.
     */
    fun violations(
        values: Map<String, String>,
        held: Map<String, String>,
        constraints: Map<String, String>,
    ): Map<String, String> =
        values
            .filter { (name, value) -> held[name] != value }
            .mapNotNull { (name, value) -> constraints[name]?.let { violation(it, value) }?.let { name to it } }
            .toMap()

    private fun compare(left: Double, operator: String, right: Double): Boolean =
        when (operator) {
            "<" -> left < right
            "<=" -> left <= right
            ">" -> left > right
            else -> left >= right
        }
}
