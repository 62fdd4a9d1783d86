package org.rtcoord.dsl

/**
 * Turns a `modes { ... }` declaration into a [ModeMachine], checking it as a whole first: names, initial modes,
 * transition targets, networks, then, once those are sound, that every mode can be reached from the start. Throws
 * [InvalidMachineException] listing every problem found.
 */
internal fun assemble(declaration: ModeBuilder, takenNames: Collection<String>): ModeMachine {
    val problems = mutableListOf<String>()
    if (declaration.name in takenNames) problems += "another machine is named '${declaration.name}'"
    val built = linkedMapOf<ModeBuilder, Mode>()

    fun build(builder: ModeBuilder, parent: Mode?): Mode {
        val path = parent?.let { "${it.path}/${builder.name}" } ?: builder.name
        val network =
            builder.network?.let { declared ->
                declared.problems.forEach { problems += "mode '$path': network: $it" }
                declared.build()
            }
        val mode = Mode(builder.name, parent, network, builder.entryActions.toList(), builder.exitActions.toList())
        built[builder] = mode
        builder.children.forEach { mode.childList += build(it, mode) }
        return mode
    }
    val root = build(declaration, null)

    val byName = built.values.groupBy { it.name }
    byName
        .filterValues { it.size > 1 }
        .forEach { (name, modes) ->
            problems += "the name '$name' is used ${modes.size} times (${modes.joinToString { it.path }})"
        }
    built.values
        .filter { it.name.isBlank() || '/' in it.name }
        .forEach { problems += "mode '${it.path}': a name must be non-blank, without '/'" }

    for ((builder, mode) in built) {
        val children = mode.children.map { it.name }
        when {
            children.isEmpty() && mode === root -> problems += "it declares no modes"
            children.isEmpty() && builder.initials.isNotEmpty() ->
                problems += "mode '${mode.path}' declares initial '${builder.initials.first()}' but has no sub-modes"
            children.isEmpty() -> {}
            builder.initials.isEmpty() ->
                problems += "${where(mode)} has sub-modes (${children.joinToString()}) but no initial(...)"
            builder.initials.size > 1 ->
                problems += "${where(mode)} declares several initial modes (${builder.initials.joinToString()})"
            builder.initials.single() !in children ->
                problems +=
                    "${where(mode)}: initial mode '${builder.initials.single()}' is not one of its sub-modes (${children.joinToString()})"
            else -> mode.initial = mode.children.first { it.name == builder.initials.single() }
        }
        if (mode === root && mode.hasExitActions)
            problems += "the machine itself is never left: exit actions on '${mode.name}' would never run"
        for (declared in builder.triggers) {
            val what = "${where(mode)}: transition ${declared.trigger.declaration}"
            val trigger = declared.trigger
            if (trigger is Trigger.Timeout && !trigger.delay.isPositive())
                problems += "$what: the delay must be positive"
            val target =
                when (declared.targets.size) {
                    0 -> null.also { problems += "$what has no goTo" }
                    1 -> declared.targets.single()
                    else -> null.also { problems += "$what goes to several modes (${declared.targets.joinToString()})" }
                } ?: continue
            val found = byName[target]?.first()
            when {
                found != null ->
                    mode.transitionList += Transition(mode, found, trigger, declared.guards.toList(), declared.action)
                target == root.name -> problems += "$what goes to the machine itself; name one of its modes"
                else ->
                    problems +=
                        "$what goes to unknown mode '$target' (modes: ${built.values.filter { it !== root }.joinToString { it.name }})"
            }
        }
    }
    if (problems.isEmpty())
        unreachable(root).forEach {
            problems += "mode '${it.path}' is unreachable: no transition leads to it or into it"
        }
    if (problems.isNotEmpty()) throw InvalidMachineException(root.name, problems)
    return ModeMachine(root)
}

private fun where(mode: Mode): String = if (mode.parent == null) "the machine" else "mode '${mode.path}'"

/** The outermost modes that no path of transitions from the start enters. */
private fun unreachable(root: Mode): List<Mode> {
    val reached = mutableSetOf<Mode>()
    val pending = ArrayDeque<Mode>()
    fun enter(mode: Mode) = (mode.lineage + mode.initialDescent).filter { reached.add(it) }.forEach { pending += it }
    enter(root)
    while (pending.isNotEmpty()) pending.removeFirst().transitions.forEach { enter(it.target) }
    return root.descendants.filter { it !in reached && it.parent in reached }
}
