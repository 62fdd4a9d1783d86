package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.NoOpCliktCommand
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument

/** `rtcoord mgr`: rtmgr, with an action word after the manager; the action does the work. */
class MgrCommand : NoOpCliktCommand("mgr") {
    init {
        subcommands(
            MgrCreateCommand(this),
            MgrDeleteCommand(this),
            MgrLoadCommand(this),
            MgrUnloadCommand(this),
            MgrListCommand(this),
        )
    }

    override fun help(context: Context): String =
        "Work with a manager: create and delete components, load and unload modules, list what it has."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord mgr /localhost/host.host_cxt/manager.mgr create odo_localise" to
                "a new component, printed as its path",
            "rtcoord mgr /localhost/host.host_cxt/manager.mgr delete odo_localise0" to
                "delete it again, by instance name",
            "rtcoord mgr /localhost/host.host_cxt/manager.mgr list factories" to "the component types it can create",
        )

    /** The manager, as its path was given. */
    val path by argument("PATH", help = "A manager (name.mgr).")
}
