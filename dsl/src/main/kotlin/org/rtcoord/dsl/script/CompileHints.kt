package org.rtcoord.dsl.script

/**
 * What to write instead, for the compiler errors that people new to the DSL meet first: the compiler
 * names the types involved, not the DSL's way of writing them.
 */
internal object CompileHints {
    private val hints = listOf(
        Regex("""actual type is '(Int|Long|Double)', but 'Duration' was expected""") to
            "a duration has a unit: 5.seconds, 500.milliseconds or 2.minutes",
        Regex("""actual type is 'Int', but 'RestartIntensity' was expected""") to
            "write how many restarts within how long: maxRestarts = 3 within 60.seconds",
        Regex("""actual type is 'String', but '(ComponentRef|PortRef)' was expected""") to
            "name it through the DSL: component(\"laser0.rtc\") or port(\"laser0.rtc:scan\")",
    )

    /** [message] with a hint appended when one fits. */
    fun withHint(message: String): String {
        val hint = hints.firstOrNull { (pattern, _) -> pattern.containsMatchIn(message) }?.second ?: return message
        return "${message.removeSuffix(".")} (hint: $hint)"
    }
}
