package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord conf PATH act SET`: switches the active configuration set. */
class ConfActCommand(private val conf: ConfCommand) : TreeCommand("act") {
    override fun help(context: Context): String =
        "Make configuration set SET the active one; this also repairs a component left with no active set."

    private val set by argument("SET", help = "The set to activate.")

    override suspend fun execute() {
        component(conf.path).activateConfigurationSet(set)
    }
}
