package org.rtcoord.bench

import kotlin.math.ceil

/** Repeated measurements of one quantity, in [unit] (`ms`, `s`, `%`, ...). */
internal class Samples(values: List<Double>, val unit: String) {
    val sorted: List<Double> = values.sorted()

    init {
        require(sorted.isNotEmpty()) { "no measurements" }
    }

    val count: Int
        get() = sorted.size

    val min: Double
        get() = sorted.first()

    val max: Double
        get() = sorted.last()

    val median: Double
        get() = percentile(50.0)

    /** The nearest-rank [p]th percentile. */
    fun percentile(p: Double): Double =
        sorted[(ceil(p / 100.0 * sorted.size).toInt() - 1).coerceIn(0, sorted.lastIndex)]

    companion object {
        /** Nanosecond durations as milliseconds. */
        fun millis(nanos: List<Long>): Samples = Samples(nanos.map { it / 1e6 }, "ms")

        /** Nanosecond durations as seconds. */
        fun seconds(nanos: List<Long>): Samples = Samples(nanos.map { it / 1e9 }, "s")
    }
}

/** [value] with three significant digits (at least one decimal below 100), as the table prints numbers. */
internal fun figure(value: Double): String =
    when {
        value.isNaN() -> "-"
        value == 0.0 -> "0"
        kotlin.math.abs(value) >= 100 -> "%.0f".format(value)
        kotlin.math.abs(value) >= 10 -> "%.1f".format(value)
        kotlin.math.abs(value) >= 1 -> "%.2f".format(value)
        else -> "%.3f".format(value)
    }

/** How [ours] compares with [theirs] (medians): `3.1x faster than rtls` or `1.4x slower than rtls`. */
internal fun speedup(ours: Samples, theirs: Samples, peer: String): String {
    val ratio = theirs.median / ours.median
    return if (ratio >= 1) "${figure(ratio)}x faster than $peer" else "${figure(1 / ratio)}x slower than $peer"
}
