package org.rtcoord.datatypes

/**
 * The repository ID a port's `dataport.data_type` means: OpenRTM-aist 1.2 and later write `IDL:RTC/TimedDouble:1.0`,
 * earlier versions and some tools `TimedDouble` or `RTC::TimedDouble`. A name without a module is one of module `RTC`,
 * as the standard types are.
 */
public object DataTypeName {
    /** `IDL:RTC/TimedDouble:1.0` for any of the forms above; an `IDL:` name as it is. */
    @JvmStatic
    public fun repositoryId(name: String): String {
        val trimmed = name.trim()
        if (trimmed.startsWith("IDL:")) return trimmed
        val scoped = trimmed.replace("::", "/").split('/').filter { it.isNotEmpty() }
        val path = if (scoped.size == 1) listOf("RTC") + scoped else scoped
        return "IDL:${path.joinToString("/")}:1.0"
    }

    /** The type's own name, `TimedDouble`, from any of the forms above. */
    @JvmStatic
    public fun simpleName(name: String): String =
        repositoryId(name).removePrefix("IDL:").substringBeforeLast(':').substringAfterLast('/')
}
