package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import org.rtcoord.NamingDirectory
import org.rtcoord.NotFoundException
import org.rtcoord.WrongKindException
import org.rtcoord.ZombieNode

/** `rtcoord del`: rtdel for dead registrations only, so a typo cannot unbind a running component. */
class DelCommand : TreeCommand("del") {
    override fun help(context: Context): String =
        "Remove dead registrations (zombies, '*' in ls) from their naming context. Live objects are refused: " +
            "stop a component with exit or mgr delete. Every PATH is checked first: if one is not a zombie, nothing is removed."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord del /localhost/host.host_cxt/crashed0.rtc" to "forget a component that died without unbinding",
            "rtcoord find /localhost --type zombie | xargs rtcoord del" to "forget every dead registration",
        )

    private val paths by argument("PATH", help = "Dead registrations in a naming context.").multiple(required = true)

    override suspend fun execute() {
        val zombies = paths.map { zombie(it) }
        eachInTurn(zombies, "unbound", { it.path.toString() }) { it.unbind() }
    }

    /** The registration at [text], if it is dead: its context is read again so that death is current. */
    private suspend fun zombie(text: String): ZombieNode {
        val path = pathOf(text)
        val parent =
            path.parent?.takeIf { path.names.isNotEmpty() && path.port == null }
                ?: throw WrongKindException(
                    path.toString(),
                    "binding in a naming context",
                    if (path.port != null) "port" else "name server",
                )
        val context =
            tree.node(parent) as? NamingDirectory
                ?: throw WrongKindException(path.toString(), "binding in a naming context", "object below a manager")
        context.refresh(1)
        return when (val node = context.children().firstOrNull { it.name == path.name }) {
            null -> throw NotFoundException(path.toString())
            is ZombieNode -> node
            else -> throw WrongKindException(path.toString(), "zombie", "live ${node.kind.label}")
        }
    }
}
