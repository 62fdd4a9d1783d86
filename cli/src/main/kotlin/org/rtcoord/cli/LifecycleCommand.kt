package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.groups.default
import com.github.ajalt.clikt.parameters.groups.mutuallyExclusiveOptions
import com.github.ajalt.clikt.parameters.groups.single
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import org.rtcoord.BadParameterException
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.LifeCycle
import org.rtcoord.OperationUnsupportedException
import org.rtcoord.PreconditionNotMetException
import org.rtcoord.RtcException
import org.rtcoord.TransitionOutcome

/**
 * A lifecycle transition of several components (`act`, `deact`, `reset`), all or nothing as far as checking goes: every
 * path must be a live component, with the chosen execution context, in the state the transition starts from (or already
 * in the one it leads to), before any component is changed. Each transition then waits until the state is reached; if
 * one fails, the error says which components were changed before it and which were not attempted. The commands differ
 * only in what they are given here.
 */
abstract class LifecycleCommand(
    name: String,
    /** The operation's name in messages: `activate`, `deactivate`, `reset`. */
    private val operation: String,
    /** What a component the operation succeeded on is, in messages: `activated`, `deactivated`, `reset`. */
    private val done: String,
    private val from: LifeCycle,
    private val to: LifeCycle,
    /** What the command does, in the help's first sentence. */
    private val does: String,
    /** The state it starts from, in the help's words (`Inactive`, `in Error`). */
    private val fromWords: String,
    /** Example command lines, each with what it does. */
    private val usage: List<Pair<String, String>>,
    /** Performs the transition on one component. */
    private val transition: suspend ComponentNode.(ContextSelector) -> TransitionOutcome,
) : TreeCommand(name) {
    override fun help(context: Context): String =
        "$does Every PATH is checked first (a live component, $fromWords or already ${stateLabel(to)}): if one is not, nothing changes."

    override fun helpEpilog(context: Context): String = examples(*usage.toTypedArray())

    private val paths by
        argument("PATH", help = "Components (name.rtc); anything else, a port path included, is refused.")
            .multiple(required = true)

    private val context by
        mutuallyExclusiveOptions(
                option(
                        "--context",
                        metavar = "HANDLE",
                        help = "The execution context with this handle (owned: 0.., participating: 1000..).",
                    )
                    .int()
                    .convert { ContextSelector.Handle(it) },
                option(
                        "--index",
                        "-e",
                        metavar = "N",
                        help = "The Nth execution context, owned ones first (rtshell's -e).",
                    )
                    .int()
                    .convert { ContextSelector.Index(it) },
            )
            .single()
            .default(ContextSelector.Handle(0))

    override suspend fun execute() {
        val pending = paths.map { checked(it) }.filter { (_, state) -> state != to }.map { (component, _) -> component }
        eachInTurn(pending, done, { it.path.toString() }) { component ->
            val outcome = component.transition(context)
            // rtact is silent on success; a transition that outlasted the context's timeout is worth a line.
            if (outcome.slow) {
                confirm(
                    "${component.path}: $done slowly: its context answered ${outcome.lateAnswer} once its transition timeout passed, ${outcome.state} after ${outcome.elapsedMillis} ms"
                )
            }
        }
    }

    /** The component at [text] and its state now, if the transition can start from it. */
    private suspend fun checked(text: String): Pair<ComponentNode, LifeCycle> {
        val component = component(text)
        val handle = component.executionContext(context).handle
        val state = component.state(context)
        if (state != from && state != to) {
            throw PreconditionNotMetException(
                component.path.toString(),
                operation,
                "the component is $state in context $handle, not $from",
            )
        }
        return component to state
    }

    /** Failures carry the ReturnCode_t they stand for, as the component gave it. */
    override fun explain(e: RtcException): String {
        val code =
            when (e) {
                is PreconditionNotMetException -> "PRECONDITION_NOT_MET"
                is BadParameterException -> "BAD_PARAMETER"
                is OperationUnsupportedException -> "UNSUPPORTED"
                else -> null
            }
        return super.explain(e) + (code?.let { " ($it)" } ?: "")
    }
}
