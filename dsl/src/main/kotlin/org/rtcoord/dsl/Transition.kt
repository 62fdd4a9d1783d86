package org.rtcoord.dsl

/**
 * A transition of a [ModeMachine]: while [source] (or any of its sub-modes) is active, [trigger] with every guard
 * holding leaves for [target]. Taking it exits the active modes up to the least common ancestor of source and target
 * (innermost first), runs its action, then enters down to the target and the target's initial modes (outermost first).
 */
public class Transition
internal constructor(
    public val source: Mode,
    public val target: Mode,
    internal val cause: Trigger,
    internal val guards: List<suspend Reaction.() -> Boolean>,
    internal val action: (suspend Reaction.() -> Unit)?,
) {
    /** What makes it go, as `check` shows it: `laser0.rtc enters ERROR`, `done`, `after 5s`. */
    public val trigger: String
        get() = cause.description

    /** Whether guards narrow it. */
    public val isGuarded: Boolean
        get() = guards.isNotEmpty()

    override fun toString(): String = "${cause.declaration}${if (isGuarded) " (guarded)" else ""} -> ${target.name}"
}
