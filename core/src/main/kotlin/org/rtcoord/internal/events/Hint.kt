package org.rtcoord.internal.events

import org.rtcoord.LifeCycle

/** What a ComponentObserver hint is about, whichever flavour sent it. */
internal enum class HintKind {
    PROFILE,
    RTC_STATUS,
    EC_STATUS,
    PORT_PROFILE,
    CONFIGURATION,
    HEARTBEAT,
    EC_HEARTBEAT,
    FSM_STATUS,
    OTHER,
}

/** One `update_status` call as received. */
internal class Hint(val kind: HintKind, val text: String) {
    /** For RTC_STATUS: the state and execution context handle it names, or null if it names none. */
    fun lifeCycle(): Pair<LifeCycle, Int>? {
        val (word, handle) = parts() ?: return null
        val state =
            when (word) {
                "ACTIVE" -> LifeCycle.ACTIVE
                "INACTIVE" -> LifeCycle.INACTIVE
                "ERROR" -> LifeCycle.ERROR
                "CREATED" -> LifeCycle.CREATED
                else -> return null
            }
        return state to handle
    }

    /** Whether it is a heartbeat, the component's or an execution context's: a sign of life and nothing else. */
    val isHeartbeat: Boolean
        get() = kind == HintKind.HEARTBEAT || kind == HintKind.EC_HEARTBEAT

    /**
     * For PORT_PROFILE: the port (without the instance prefix) and whether it sent (true) or received data, from
     * OpenRTM's `SEND:OutPort:<instance>.<port>` and `RECEIVE:InPort:<instance>.<port>` (the middle field is optional
     * here); null for any other hint.
     */
    fun traffic(): Pair<String, Boolean>? {
        if (kind != HintKind.PORT_PROFILE) return null
        val fields = text.split(':').map { it.trim() }
        if (fields.size !in 2..3) return null
        val outgoing =
            when (fields[0].uppercase()) {
                "SEND" -> true
                "RECEIVE" -> false
                else -> return null
            }
        val port = fields.last().substringAfter('.').takeIf { it.isNotEmpty() } ?: return null
        return port to outgoing
    }

    /**
     * For FSM_STATUS: the state an FSM component entered, from StaticFSM's `<state> POST_ONENTRY` (sent once the
     * state's entry action ran); null for any other hint, the other actions of a transition too.
     */
    fun fsmEntered(): String? {
        if (kind != HintKind.FSM_STATUS) return null
        val words = text.trim().split(' ').filter { it.isNotEmpty() }
        return words.takeIf { it.size == 2 && it[1].equals("POST_ONENTRY", ignoreCase = true) }?.first()
    }

    /** Whether it is OpenRTM's `FINALIZE:0`, sent when the component exits. */
    val isFinalize: Boolean
        get() = kind == HintKind.RTC_STATUS && parts()?.first == "FINALIZE"

    /** `WORD:handle`, leniently: spaces trimmed, case ignored. Null when malformed. */
    private fun parts(): Pair<String, Int>? {
        val fields = text.split(':')
        if (fields.size != 2) return null
        val handle = fields[1].trim().toIntOrNull() ?: return null
        return fields[0].trim().uppercase() to handle
    }

    override fun toString(): String = "$kind '$text'"

    companion object {
        private val OPENRTM =
            listOf(
                HintKind.PROFILE,
                HintKind.RTC_STATUS,
                HintKind.EC_STATUS,
                HintKind.PORT_PROFILE,
                HintKind.CONFIGURATION,
                HintKind.HEARTBEAT,
            )
        private val OMG =
            listOf(
                HintKind.PROFILE,
                HintKind.RTC_STATUS,
                HintKind.EC_STATUS,
                HintKind.PORT_PROFILE,
                HintKind.CONFIGURATION,
                HintKind.HEARTBEAT,
                HintKind.EC_HEARTBEAT,
                HintKind.OTHER,
                HintKind.FSM_STATUS,
            )

        fun openRtm(kind: OpenRTM.StatusKind, text: String?) =
            Hint(OPENRTM.getOrElse(kind.value()) { HintKind.OTHER }, text.orEmpty())

        fun omg(kind: RTC.StatusKind, text: String?) =
            Hint(OMG.getOrElse(kind.value()) { HintKind.OTHER }, text.orEmpty())
    }
}
