package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord mgr PATH load MODULE`: loads a module into the manager. */
class MgrLoadCommand(private val mgr: MgrCommand) : TreeCommand("load") {
    override fun help(context: Context): String =
        "Load module MODULE (a file the manager can reach), making its component types creatable."

    private val module by argument("MODULE", help = "The module's file, as the manager names it.")

    private val init by
        option("--init", metavar = "FUNCTION", help = "The module's initialisation function, if the manager needs it.")
            .default("")

    override suspend fun execute() {
        manager(mgr.path).loadModule(module, init)
    }
}
