package org.rtcoord.dsl

/**
 * The modes of the whole system a script declares with `modes("system") { ... }`: a tree of [Mode]s under [root],
 * checked when the declaration ends (see [InvalidMachineException]). A [org.rtcoord.dsl.Coordinator] runs it;
 * [RunningMachine] shows where it is.
 */
public class ModeMachine
internal constructor(
    /** The machine's top: always active, named after the machine, holding the modes declared at the top. */
    public val root: Mode
) {
    /** The machine's name. */
    public val name: String
        get() = root.name

    /** Every mode below [root], each before its sub-modes. */
    public val modes: List<Mode>
        get() = root.descendants

    /** The machine as `check` lists it: one line per mode, network constraint and transition, indented by nesting. */
    public val description: List<String>
        get() = describe(root, 0)

    /** The event patterns of every transition, each to be watched for as long as the machine runs. */
    internal val eventPatterns: List<EventPattern<*>>
        get() = (listOf(root) + modes).flatMap { it.transitions }.mapNotNull { (it.cause as? Trigger.Event)?.pattern }

    private fun describe(mode: Mode, depth: Int): List<String> {
        val indent = "  ".repeat(depth)
        val heading = buildList {
            add(if (mode === root) "modes ${mode.name}" else "mode ${mode.name}")
            mode.initial?.let { add("initially ${it.name}") }
            if (mode.hasEntryActions) add("entry")
            if (mode.hasExitActions) add("exit")
        }
            .joinToString(", ")
        return listOf(indent + heading) +
            mode.network?.description.orEmpty().map { "$indent  network: $it" } +
            mode.transitions.map { "$indent  $it" } +
            mode.children.flatMap { describe(it, depth + 1) }
    }
}
