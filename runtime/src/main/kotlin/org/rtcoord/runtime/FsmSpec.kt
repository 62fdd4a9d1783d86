package org.rtcoord.runtime

/**
 * A hierarchical state machine as OpenRTM-aist's StaticFSM (Macho) runs one in an FSM component: states nested below
 * one top state, each composite state entering a child from its `onInit`, an event handled by the current state or the
 * nearest state above it that handles it. A transition leaves states up to the one holding the target, enters down to
 * the target, then runs the target's `onInit` (which may enter a child, and so on).
 */
public class FsmSpec(
    /** The machine's name, as its component calls it. */
    public val name: String,
    /** Each state's parent; the top state's is null. */
    public val parents: Map<String, String?>,
    /** The child each composite state's `onInit` enters. */
    public val initial: Map<String, String>,
    /** The state an event leads to, by the state that handles it and the event's name. */
    public val transitions: Map<Pair<String, String>, String>,
) {
    /** The top state. */
    public val top: String =
        parents.entries.singleOrNull { it.value == null }?.key
            ?: throw IllegalArgumentException("$name needs exactly one top state")

    init {
        val unknown =
            (parents.values.filterNotNull() +
                    initial.keys +
                    initial.values +
                    transitions.keys.map { it.first } +
                    transitions.values)
                .filter { it !in parents }
        require(unknown.isEmpty()) { "$name names states it does not declare: ${unknown.distinct()}" }
    }

    /** [state] and the states above it, innermost first. */
    internal fun lineage(state: String): List<String> = generateSequence(state) { parents[it] }.toList()

    /** The events some state handles. */
    public val events: Set<String>
        get() = transitions.keys.map { it.second }.toSet()
}
