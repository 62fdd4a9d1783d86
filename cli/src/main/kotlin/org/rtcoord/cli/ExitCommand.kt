package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple

/** `rtcoord exit`: rtexit, checking every path before any component is asked to go. */
class ExitCommand : TreeCommand("exit") {
    override fun help(context: Context): String =
        "Ask components to exit: each finalises and leaves its execution contexts; the command returns once its " +
            "manager has unbound it from naming. Every PATH is checked first (a live component): if one is not, no component is asked."

    override fun helpEpilog(context: Context): String =
        examples("rtcoord exit /localhost/host.host_cxt/laser_localise0.rtc" to "stop the laser localiser for good")

    private val paths by
        argument("PATH", help = "Components (name.rtc); anything else, a port path included, is refused.")
            .multiple(required = true)

    override suspend fun execute() {
        val components = paths.map { text -> component(text).also { it.refresh() } }
        eachInTurn(components, "exited", { it.path.toString() }) { it.exit() }
    }
}
