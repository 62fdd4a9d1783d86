package org.rtcoord.cli

import com.github.ajalt.clikt.parameters.options.NullableOption
import com.github.ajalt.clikt.parameters.options.RawOption
import com.github.ajalt.clikt.parameters.options.convert
import kotlin.time.Duration

/** An option holding a positive duration in Kotlin's notation: `3s`, `500ms`, `2m`, `1h 30m`. */
fun RawOption.duration(): NullableOption<Duration, Duration> =
    convert("DURATION") { text ->
        Duration.parseOrNull(text)?.takeIf { it.isPositive() }
            ?: fail("'$text' is not a positive duration such as 3s or 500ms")
    }
