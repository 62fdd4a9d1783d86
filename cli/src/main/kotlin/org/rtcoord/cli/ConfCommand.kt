package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord conf`: rtconf, with an action word after the component. */
class ConfCommand : TreeCommand("conf") {
    private val list = ConfListCommand(this)

    init {
        subcommands(list, ConfGetCommand(this), ConfSetCommand(this), ConfActCommand(this))
    }

    override val invokeWithoutSubcommand: Boolean = true

    override fun help(context: Context): String =
        "Read and change a component's configuration: list its sets (the default), get or set a parameter, activate a set."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord conf /localhost/host.host_cxt/laser_localise0.rtc" to "every set, the active one marked '*'",
            "rtcoord conf /localhost/host.host_cxt/laser_localise0.rtc get gain" to "one value from the active set",
            "rtcoord conf /localhost/host.host_cxt/laser_localise0.rtc set gain 0.8 --set precise" to
                "change a value in another set",
            "rtcoord conf /localhost/host.host_cxt/laser_localise0.rtc act precise" to "make a set the active one",
        )

    /** The component, as its path was given. */
    val path by argument("PATH", help = "A component (name.rtc).")

    override suspend fun execute() {
        if (currentContext.invokedSubcommand == null) list.show(set = null, all = false)
    }
}
