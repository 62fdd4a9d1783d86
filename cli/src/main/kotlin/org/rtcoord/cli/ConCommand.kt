package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.PreconditionNotMetException
import org.rtcoord.cli.json.ConnectorJson

/** `rtcoord con`: rtcon, refusing incompatible ports and a second connection of two ports before anything changes. */
class ConCommand : TreeCommand("con") {
    override fun help(context: Context): String =
        "Connect two ports and print the new connector's id. Data ports get OpenRTM's usual properties (push, corba_cdr, " +
            "flush, the out-port's data type) unless --property says otherwise; ports whose data types or offered " +
            "properties do not match are refused, and so are ports connected already, as OpenRTM-aist refuses them " +
            "(--allow-duplicate connects them again)."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord con /localhost/host.host_cxt/laser0.rtc:laser /localhost/host.host_cxt/laser_localise0.rtc:laser" to
                "a data connection",
            "rtcoord con A.rtc:out B.rtc:in -p dataport.subscription_type=new --name fast" to
                "with a property and a name",
            "rtcoord con A.rtc:out B.rtc:in --allow-duplicate" to "a second connection of two connected ports",
        )

    private val from by argument("PATH:PORT", help = "One port.")

    private val to by argument("PATH:PORT", help = "The other port.")

    private val name by
        option("--name", metavar = "N", help = "The connector's name (default: both ports' names joined).")

    private val id by option("--id", metavar = "ID", help = "The connector's id (default: chosen by the component).")

    private val properties by
        option("--property", "-p", metavar = "KEY=VALUE", help = "A connector property (repeatable).")
            .convert { text ->
                val (key, value) =
                    text.split('=', limit = 2).takeIf { it.size == 2 && it[0].isNotBlank() }
                        ?: fail("'$text' is not KEY=VALUE")
                key.trim() to value.trim()
            }
            .multiple()

    private val allowDuplicate by
        option(
                "--allow-duplicate",
                help =
                    "Connect ports that are connected already: OpenRTM-aist refuses that unless the connector carries " +
                        "$ALLOW_DUPLICATE=YES, which this sets.",
            )
            .flag()

    override suspend fun execute() {
        val source = port(from)
        val target = port(to)
        val given = properties.toMap()
        val duplicates = given[ALLOW_DUPLICATE].equals("YES", ignoreCase = true) || allowDuplicate
        // A port given twice is refused by connect itself, with its own reason.
        if (!duplicates && source.path != target.path) {
            val existing = source.connectorsTo(target)
            if (existing.isNotEmpty()) {
                throw PreconditionNotMetException(
                    source.path.toString(),
                    "connect",
                    "already connected to ${target.path} (connector ${existing.joinToString { it.id }}); --allow-duplicate connects them again",
                )
            }
        }
        val connector =
            source.connect(
                listOf(target),
                if (allowDuplicate) given + (ALLOW_DUPLICATE to "YES") else given,
                name,
                id.orEmpty(),
            )
        if (session.json) {
            echoJson(ConnectorJson(connector.id, connector.name, connector.properties.toSortedMap()))
        } else {
            confirm(connector.id)
        }
    }
}

/** The connector property with which OpenRTM-aist's ports accept a second connection between them. */
private const val ALLOW_DUPLICATE = "dataport.allow_dup_connection"
