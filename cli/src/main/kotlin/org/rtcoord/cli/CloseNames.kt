package org.rtcoord.cli

/**
 * The names among [candidates] close enough to [wanted] to be what was meant: a few typing mistakes apart (edit
 * distance, ignoring case, at most a quarter of the name's length and never more than 3), or [wanted] without the kind
 * an rtshell name carries (`laser0` for `laser0.rtc`). Nearest first, at most three.
 */
internal fun closeNames(wanted: String, candidates: Collection<String>): List<String> {
    val limit = (wanted.length / 4).coerceIn(1, 3)
    return candidates
        .asSequence()
        .map { candidate ->
            candidate to
                minOf(editDistance(wanted, candidate), editDistance(wanted, candidate.substringBeforeLast('.')))
        }
        .filter { (candidate, distance) -> distance <= limit && candidate != wanted }
        .sortedWith(compareBy({ it.second }, { it.first }))
        .map { it.first }
        .distinct()
        .take(3)
        .toList()
}

/** The "; did you mean ...?" to append to a not-found reason, or "" when nothing is close. */
internal fun didYouMean(wanted: String, candidates: Collection<String>): String =
    closeNames(wanted, candidates)
        .takeIf { it.isNotEmpty() }
        ?.let { "; did you mean ${it.joinToString(" or ")}?" }
        .orEmpty()

/** Levenshtein distance between [a] and [b], ignoring case. */
private fun editDistance(a: String, b: String): Int {
    val x = a.lowercase()
    val y = b.lowercase()
    var previous = IntArray(y.length + 1) { it }
    for (i in 1..x.length) {
        val current = IntArray(y.length + 1)
        current[0] = i
        for (j in 1..y.length) {
            val substitution = previous[j - 1] + if (x[i - 1] == y[j - 1]) 0 else 1
            current[j] = minOf(substitution, previous[j] + 1, current[j - 1] + 1)
        }
        previous = current
    }
    return previous[y.length]
}
