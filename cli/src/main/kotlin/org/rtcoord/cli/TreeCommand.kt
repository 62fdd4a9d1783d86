package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.core.requireObject
import kotlinx.coroutines.runBlocking
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.ManagerNode
import org.rtcoord.NameServerNode
import org.rtcoord.Node
import org.rtcoord.NotFoundException
import org.rtcoord.Port
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.WrongKindException
import org.rtcoord.cli.json.PrettyJson

/**
 * A subcommand working on the RT system through the [Session]'s tree. It turns every failure into the one-line error of
 * [CommandFailed]; `-v` adds the stack trace.
 */
abstract class TreeCommand(name: String) : CliktCommand(name) {
    /** The run's shared settings and tree, set up by [Rtcoord]. */
    protected val session: Session by requireObject()

    /** The tree, created on first use. */
    protected val tree: RtcTree
        get() = session.tree

    /** Does the command's work. */
    protected abstract suspend fun execute()

    final override fun run() {
        try {
            runBlocking {
                try {
                    execute()
                } catch (e: NotFoundException) {
                    throw suggesting(e)
                }
            }
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

    /** Why [server] does not answer a listing now; null when it does. */
    protected suspend fun unreachable(server: NameServerNode): RtcException? =
        try {
            server.refresh()
            null
        } catch (e: RtcException) {
            e
        }

    /** Prints [value] as JSON, indented. */
    internal inline fun <reified T> echoJson(value: T) {
        echo(PrettyJson.encodeToString(value))
    }

    /** Prints a confirmation, unless `-q`. */
    protected fun confirm(line: String) {
        if (!session.quiet) echo(line)
    }

    /**
     * Where discovery reports progress: stderr on a terminal, nowhere when the output is piped (or with `-q`), so
     * scripts never see it.
     */
    internal fun progressLine(): StatusLine? =
        if (System.console() != null && !session.quiet) StatusLine { echo(it, trailingNewline = false, err = true) }
        else null

    /**
     * [text] read as a path, relative ones from the session's [start][Session.start]; with nothing to start from, a
     * relative path fails saying how to give a start.
     */
    protected fun pathOf(text: String): RtcPath {
        val start = session.start
        if (start == null && !text.startsWith('/') && !text.startsWith("corbaloc:", ignoreCase = true)) {
            fail(
                "$text: a relative path needs a start: give -n HOST[:PORT] (relative paths start at the first name server) or set RTCOORD_CWD"
            )
        }
        return RtcPath(text, start)
    }

    /**
     * The node at [text]; a port path is refused rather than read as its component, and so is the root when no name
     * server is configured (it would list nothing).
     */
    protected suspend fun node(text: String): Node {
        val path = pathOf(text)
        if (path.port != null) throw WrongKindException(path.toString(), "component, manager or directory", "port")
        if (path.isRoot && session.nameServers.isEmpty()) fail("$text: $NO_NAME_SERVER")
        return tree.node(path)
    }

    /**
     * Where a command that follows a whole system (serve, record) starts: the node at [text], or for `/` the one name
     * server given (the root when there are several); `/` with none is a usage error.
     */
    protected suspend fun systemTop(text: String): Node {
        if (!pathOf(text).isRoot) return node(text)
        if (session.nameServers.isEmpty()) usage("no name server: give PATH (/HOST:PORT) or -n HOST")
        return tree.nameServers.singleOrNull() ?: tree.root
    }

    /** The component at [text]; a port path is refused rather than read as its component. */
    protected suspend fun component(text: String): ComponentNode =
        tree.component(objectPath(text, "component").toString())

    /** The manager at [text]; a port path is refused. */
    protected suspend fun manager(text: String): ManagerNode = tree.manager(objectPath(text, "manager").toString())

    /** The port at [text] (`component.rtc:port`). */
    protected suspend fun port(text: String): Port = tree.port(pathOf(text).toString())

    /** [text] as a path, refused if it names a port where a [kind] is wanted. */
    private fun objectPath(text: String, kind: String): RtcPath =
        pathOf(text).also { if (it.port != null) throw WrongKindException(it.toString(), kind, "port") }

    /**
     * [e] with the names close to the one not found, from where it was looked for: the directory that lacks a name, the
     * component that lacks a port. [e] itself when nothing is close or it cannot tell.
     */
    private suspend fun suggesting(e: NotFoundException): NotFoundException {
        val path = runCatching { RtcPath(e.subject) }.getOrNull() ?: return e
        val hint = runCatching {
            val port = path.port
            when {
                port != null && e.reason.startsWith("no such port") ->
                    didYouMean(port, tree.component(path.withPort(null).toString()).snapshot().ports.map { it.name })
                port == null && e.reason == "not found" ->
                    (path.parent?.let { tree.node(it) } as? DirectoryNode)
                        ?.let { directory -> didYouMean(path.name, directory.children().map { it.name }) }
                        .orEmpty()
                else -> ""
            }
        }
            .getOrDefault("")
        return if (hint.isEmpty()) e else NotFoundException(e.subject, e.reason + hint)
    }
}

/** What to say when a command needs a name server and none was given. */
internal const val NO_NAME_SERVER =
    "no name server configured: give -n HOST[:PORT], or set RTCOORD_NAMESERVERS (or rtshell's RTCTREE_NAMESERVERS), e.g. RTCOORD_NAMESERVERS=localhost"
