package org.rtcoord.runtime

import RTC.ExtendedFsmServicePOA
import RTC.FsmEventProfile
import RTC.FsmStructure
import RTC.FsmStructureHolder
import RTC.ReturnCode_t
import _SDOPackage.NameValue

/**
 * A component's running [FsmSpec] and the `ExtendedFsmService` it offers, as OpenRTM-aist 2.0 has them. Each state left
 * and entered is told to the FSM4RTC observers as StaticFSM's action listeners tell it (`Idle PRE_ON_EXIT`, `Idle
 * POST_ON_EXIT`, `Idle PRE_ON_STATE_CHANGE`, `Programmed POST_ON_STATE_CHNAGE`, `Programmed PRE_ONENTRY`, `Programmed
 * POST_ONENTRY`, `Programmed PRE_ON_INIT`, `Programmed POST_ON_INIT`, the library's own spellings). The service is
 * OpenRTM-aist's provider: `get_current_state` answers the state only its `changeStatus` sets, which nothing in the
 * library calls, so `""`; `get_fsm_structure` answers the structure last set, at first the provider's placeholder
 * (`dummy_name`, two states and a `toggle` event, format `scxml`).
 */
internal class RuntimeFsm(
    private val spec: FsmSpec,
    private val hint: (String) -> Unit,
    private val nameValue: (String, String) -> NameValue,
) : ExtendedFsmServicePOA() {
    private val lock = Any()
    private var current: String = spec.top
    private var structure =
        FsmStructure(
            "dummy_name",
            PLACEHOLDER,
            arrayOf(FsmEventProfile("toggle", "TimedShort")),
            arrayOf(nameValue("fsm_structure.format", "scxml")),
        )

    init {
        synchronized(lock) { initialise(spec.top) }
    }

    /** The state the machine is in (a leaf, after its `onInit` ran). */
    val state: String
        get() = synchronized(lock) { current }

    /**
     * Handles [event] as Macho dispatches it; returns the state it leads to, or throws if no state handles it there.
     */
    fun dispatch(event: String): String =
        synchronized(lock) {
            val handler =
                spec.lineage(current).firstOrNull { (it to event) in spec.transitions }
                    ?: throw IllegalArgumentException(
                        "${spec.name}: no state from $current up handles '$event' (events: ${spec.events.sorted().joinToString()})"
                    )
            val target = spec.transitions.getValue(handler to event)
            val targetLine = spec.lineage(target)
            // A transition to the current state or one above it leaves and enters that state again.
            val holder = spec.lineage(current).firstOrNull { it in targetLine && it != target }
            val leaving = spec.lineage(current).takeWhile { it != holder }
            val entering = targetLine.takeWhile { it != holder }.reversed()
            for (state in leaving) listOf("PRE_ON_EXIT", "POST_ON_EXIT", "PRE_ON_STATE_CHANGE").forEach {
                hint("$state $it")
            }
            entering.forEach(::enter)
            initialise(target)
            current
        }

    private fun enter(state: String) {
        listOf("POST_ON_STATE_CHNAGE", "PRE_ONENTRY", "POST_ONENTRY").forEach { hint("$state $it") }
        current = state
    }

    /** Runs [state]'s `onInit`, entering its initial child and that one's, down to a leaf. */
    private fun initialise(state: String) {
        current = state
        var next: String? = state
        while (next != null) {
            hint("$next PRE_ON_INIT")
            hint("$next POST_ON_INIT")
            next = spec.initial[next]?.also(::enter)
        }
    }

    override fun get_current_state(): String = ""

    override fun set_fsm_structure(structure: FsmStructure): ReturnCode_t {
        synchronized(lock) { this.structure = structure }
        return ReturnCode_t.RTC_OK
    }

    override fun get_fsm_structure(structure: FsmStructureHolder): ReturnCode_t {
        structure.value = synchronized(lock) { this.structure }
        return ReturnCode_t.RTC_OK
    }

    private companion object {
        /** ExtendedFsmServiceProvider's placeholder structure, in substance. */
        const val PLACEHOLDER =
            "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" initial=\"airline-ticket\">" +
                "<state id=\"state0\"><transition event=\"toggle\" target=\"state1\"/></state>" +
                "<state id=\"state1\"><transition event=\"toggle\" target=\"state0\"/></state></scxml>"
    }
}
