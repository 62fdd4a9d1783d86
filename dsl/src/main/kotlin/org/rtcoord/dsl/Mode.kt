package org.rtcoord.dsl

/**
 * A mode of a [ModeMachine], as declared: where it sits, its sub-modes and initial one, its transitions and the network
 * it needs. While a mode is active so are all its ancestors, and its transitions apply in any of its sub-modes.
 *
 * @property name its name, unique in its machine.
 * @property parent the mode it is nested in; null for the machine's top, named after the machine.
 * @property network the network it declares; null when it declares none.
 */
public class Mode
internal constructor(
    public val name: String,
    public val parent: Mode?,
    public val network: Network?,
    internal val entryActions: List<suspend Reaction.() -> Unit>,
    internal val exitActions: List<suspend Reaction.() -> Unit>,
) {
    internal val childList = mutableListOf<Mode>()
    internal val transitionList = mutableListOf<Transition>()

    /** `machine/outer/this`. */
    public val path: String = parent?.let { "${it.path}/$name" } ?: name

    /** Its sub-modes, in declaration order. */
    public val children: List<Mode>
        get() = childList

    /** The sub-mode entered when this mode is; null for a mode without sub-modes. */
    public var initial: Mode? = null
        internal set

    /** Its transitions, in declaration order: the first one whose trigger and guards match is taken. */
    public val transitions: List<Transition>
        get() = transitionList

    /** Whether it has entry actions. */
    public val hasEntryActions: Boolean
        get() = entryActions.isNotEmpty()

    /** Whether it has exit actions. */
    public val hasExitActions: Boolean
        get() = exitActions.isNotEmpty()

    /** The machine's top first, this mode last. */
    internal val lineage: List<Mode>
        get() = generateSequence(this) { it.parent }.toList().asReversed()

    /** Every mode below this one, each before its sub-modes. */
    internal val descendants: List<Mode>
        get() = childList.flatMap { listOf(it) + it.descendants }

    /** The modes entered below this one when it is entered: its initial mode, that one's, and so on. */
    internal val initialDescent: List<Mode>
        get() = generateSequence(initial) { it.initial }.toList()

    override fun toString(): String = path
}
