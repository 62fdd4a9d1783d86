package org.rtcoord.dsl.script

import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.LogLevel

/**
 * How scripts name log levels: bare (`logged(WARN)`), each but ERROR, which bare is the lifecycle state (both enums
 * imported whole would make it ambiguous in every `state(ERROR)`). Where a level is wanted, the words that take one
 * also take the state [LifeCycle.ERROR] and read it as [LogLevel.ERROR] ([of]), so `logged(ERROR)` reads as written.
 */
@InternalRtcoordApi
public object LogLevelNames {
    /** The default imports that name every level but ERROR bare. */
    public val imports: List<String> =
        LogLevel.entries.filter { it != LogLevel.ERROR }.map { "org.rtcoord.LogLevel.${it.name}" }

    /** [state] where a script wrote ERROR for a log level: [LogLevel.ERROR]; any other state is no level. */
    public fun of(state: LifeCycle): LogLevel {
        require(state == LifeCycle.ERROR) { "$state is a lifecycle state, not a log level" }
        return LogLevel.ERROR
    }
}
