package org.rtcoord.dsl.script

/**
 * What to write instead, for the compiler errors that people new to the DSL meet first: the compiler names the types
 * involved, not the DSL's way of writing them.
 */
internal object CompileHints {
    private val duration = Regex("""actual type is '(Int|Long|Double)', but 'Duration' was expected""")
    private val simple = Regex("""[\w.]+""")

    private val hints =
        listOf(
            Regex("""actual type is 'Int', but 'RestartIntensity' was expected""") to
                "write how many restarts within how long: maxRestarts = 3 within 60.seconds",
            Regex("""actual type is 'String', but '(ComponentRef|PortRef)' was expected""") to
                "name it through the DSL: component(\"laser0.rtc\") or port(\"laser0.rtc:scan\")",
        )

    /** [message] with a hint appended when one fits; [written] is the code the error is about, when known. */
    fun withHint(message: String, written: String? = null): String {
        val hint =
            if (duration.containsMatchIn(message)) durationHint(written)
            else hints.firstOrNull { (pattern, _) -> pattern.containsMatchIn(message) }?.second ?: return message
        return "${message.removeSuffix(".")} (hint: $hint)"
    }

    /** `write 5.seconds` for a number written where a duration is expected, in the script's own terms. */
    private fun durationHint(written: String?): String {
        val amount =
            written?.trim()?.takeIf { it.isNotEmpty() }
                ?: return "a duration has a unit: 5.seconds, 500.milliseconds or 2.minutes"
        val receiver = if (simple.matches(amount)) amount else "($amount)"
        return "a duration has a unit: write $receiver.seconds (or $receiver.milliseconds, $receiver.minutes)"
    }
}
