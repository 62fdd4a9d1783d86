package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.core.requireObject
import kotlinx.coroutines.runBlocking
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.Port
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.WrongKindException

/**
 * A subcommand working on the RT system through the [Session]'s tree. It turns every failure into
 * the one-line error of [CommandFailed]; `-v` adds the stack trace.
 */
abstract class TreeCommand(name: String) : CliktCommand(name) {
    /** The run's shared settings and tree, set up by [Rtcoord]. */
    protected val session: Session by requireObject()

    /** The tree, created on first use. */
    protected val tree: RtcTree get() = session.tree

    /** Does the command's work. */
    protected abstract suspend fun execute()

    final override fun run() {
        try {
            runBlocking { execute() }
        } catch (e: CliktError) {
            throw e
        } catch (e: PartlyDone) {
            fail("${explain(e.failure)}; ${e.progress}", e)
        } catch (e: RtcException) {
            fail(explain(e), e)
        } catch (e: IllegalArgumentException) {
            // The library's argument checks (require) explain themselves.
            fail(e.message ?: e.toString(), e)
        } catch (e: Exception) {
            // Still one line, as promised; -v shows where it came from.
            fail("unexpected failure: $e", e)
        }
    }

    /** The message for [e]; commands that know more about their failures say it here. */
    protected open fun explain(e: RtcException): String = e.message ?: e.reason

    /** Ends the command with `rtcoord: [what]` and status 1; with `-v`, [cause]'s stack trace first. */
    protected fun fail(what: String, cause: Throwable? = null): Nothing {
        if (session.verbose && cause != null) echo(cause.stackTraceToString().trimEnd(), err = true)
        throw CommandFailed(what)
    }

    /** Ends the command with a usage error (status 2) about this command's arguments. */
    protected fun usage(what: String): Nothing = throw UsageError(what).apply { context = currentContext }

    /** Prints [value] as JSON. */
    protected fun echoJson(value: Any?) {
        echo(toJson(value))
    }

    /** Prints a confirmation, unless `-q`. */
    protected fun confirm(line: String) {
        if (!session.quiet) echo(line)
    }

    /**
     * Where discovery reports progress: stderr on a terminal, nowhere when the output is piped (or
     * with `-q`), so scripts never see it.
     */
    internal fun progressLine(): StatusLine? =
        if (System.console() != null && !session.quiet) StatusLine { echo(it, trailingNewline = false, err = true) } else null

    /** [text] read as a path, relative ones from the working directory. */
    protected fun pathOf(text: String): RtcPath = RtcPath.parse(text, session.workingDirectory)

    /** The node at [text]; a port path is refused rather than read as its component. */
    protected suspend fun node(text: String): Node {
        val path = pathOf(text)
        if (path.port != null) throw WrongKindException(path.toString(), "component, manager or directory", "port")
        return tree.node(path)
    }

    /** The component at [text]. */
    protected suspend fun component(text: String): ComponentNode = tree.component(text, session.workingDirectory)

    /** The manager at [text]. */
    protected suspend fun manager(text: String): ManagerNode = tree.manager(text, session.workingDirectory)

    /** The port at [text] (`component.rtc:port`). */
    protected suspend fun port(text: String): Port = tree.port(text, session.workingDirectory)
}
