package org.rtcoord.cli.json

import kotlinx.serialization.Serializable
import org.rtcoord.WatchMethod

/** How a component is watched, as `watch` and the live view give it: [method] names the kind. */
@Serializable
internal sealed class WatchMethodJson {
    /** `pushed`, `polled` or `unwatched`. */
    abstract val method: String

    /** Events pushed by the component's [observer] (its repository id), with a heartbeat and, when set, polling too. */
    @Serializable
    class Pushed
    private constructor(
        override val method: String,
        val observer: String,
        val heartbeatMillis: Long,
        /** How often it is also polled; null when it is not. */
        val pollPeriodMillis: Long?,
    ) : WatchMethodJson() {
        constructor(
            observer: String,
            heartbeatMillis: Long,
            pollPeriodMillis: Long?,
        ) : this("pushed", observer, heartbeatMillis, pollPeriodMillis)
    }

    /** Polled every [pollPeriodMillis], for [reason]. */
    @Serializable
    class Polled private constructor(override val method: String, val pollPeriodMillis: Long, val reason: String) :
        WatchMethodJson() {
        constructor(pollPeriodMillis: Long, reason: String) : this("polled", pollPeriodMillis, reason)
    }

    /** Not watched at all, for [reason]. */
    @Serializable
    class Unwatched private constructor(override val method: String, val reason: String) : WatchMethodJson() {
        constructor(reason: String) : this("unwatched", reason)
    }

    companion object {
        /** [method] as the JSON gives it. */
        fun of(method: WatchMethod): WatchMethodJson =
            when (method) {
                is WatchMethod.Pushed ->
                    Pushed(
                        method.flavour.repositoryId,
                        method.heartbeat.inWholeMilliseconds,
                        method.pollPeriod?.inWholeMilliseconds,
                    )
                is WatchMethod.Polled -> Polled(method.period.inWholeMilliseconds, method.reason)
                is WatchMethod.Unwatched -> Unwatched(method.reason)
            }
    }
}
