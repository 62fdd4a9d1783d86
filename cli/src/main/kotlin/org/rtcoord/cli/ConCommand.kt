package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord con`: rtcon, refusing incompatible ports before anything changes. */
class ConCommand : TreeCommand("con") {
    override fun help(context: Context): String =
        "Connect two ports and print the new connector's id. Data ports get OpenRTM's usual properties (push, corba_cdr, " +
            "flush, the out-port's data type) unless --property says otherwise; ports whose data types or offered " +
            "properties do not match are refused."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord con /localhost/host.host_cxt/laser0.rtc:laser /localhost/host.host_cxt/laser_localise0.rtc:laser" to "a data connection",
        "rtcoord con A.rtc:out B.rtc:in -p dataport.subscription_type=new --name fast" to "with a property and a name",
    )

    private val from by argument("PATH:PORT", help = "One port.")

    private val to by argument("PATH:PORT", help = "The other port.")

    private val name by option("--name", metavar = "N", help = "The connector's name (default: both ports' names joined).")

    private val id by option("--id", metavar = "ID", help = "The connector's id (default: chosen by the component).")

    private val properties by option("--property", "-p", metavar = "KEY=VALUE", help = "A connector property (repeatable).")
        .convert { text ->
            val (key, value) = text.split('=', limit = 2).takeIf { it.size == 2 && it[0].isNotBlank() } ?: fail("'$text' is not KEY=VALUE")
            key.trim() to value.trim()
        }.multiple()

    override suspend fun execute() {
        val connector = port(from).connect(listOf(port(to)), properties.toMap(), name, id.orEmpty())
        if (session.json) {
            echoJson(mapOf("id" to connector.id, "name" to connector.name, "properties" to connector.properties.toSortedMap()))
        } else {
            confirm(connector.id)
        }
    }
}
