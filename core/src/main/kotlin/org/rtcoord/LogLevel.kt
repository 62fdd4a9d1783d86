package org.rtcoord

/**
 * How severe a component's log record is: OpenRTM-aist's logger levels, most severe first. A level includes those above
 * it: a rule on [WARN] hears [WARN], [ERROR] and [FATAL].
 */
public enum class LogLevel {
    FATAL,
    ERROR,
    WARN,
    INFO,
    DEBUG,
    TRACE,
    VERBOSE,
    PARANOID;

    /** Whether a record at this level is at least as severe as [threshold]. */
    public fun atLeast(threshold: LogLevel): Boolean = ordinal <= threshold.ordinal

    public companion object {
        /**
         * The level a record names: OpenRTM-aist's names in any case, and the names Python's `logging` gives the same
         * levels (`WARNING`, `CRITICAL`), which OpenRTM-aist-Python's FluentLogger sends for warnings; null for any
         * other name.
         */
        @JvmStatic
        public fun named(name: String): LogLevel? =
            // Senders name levels as OpenRTM-aist writes them: the exact name is looked up first, as often as records
            // come.
            entries.firstOrNull { it.name == name }
                ?: when (val upper = name.trim().uppercase()) {
                    "WARNING" -> WARN
                    "CRITICAL" -> FATAL
                    else -> entries.firstOrNull { it.name == upper }
                }
    }
}
