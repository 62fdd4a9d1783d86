package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.NoOpCliktCommand
import com.github.ajalt.clikt.core.subcommands
import org.rtcoord.profile.OrderedAction

/**
 * `rtcoord profile`: RTSProfiles, as RTSystemEditor and rtshell's rtcryo, rtresurrect, rtcheck, rtstart, rtstop,
 * rtteardown.
 */
class ProfileCommand : NoOpCliktCommand("profile") {
    init {
        subcommands(
            ProfileSaveCommand(),
            ProfileRestoreCommand(),
            ProfileCheckCommand(),
            ProfileOrderCommand("start", OrderedAction.START),
            ProfileOrderCommand("stop", OrderedAction.STOP),
            ProfileTeardownCommand(),
        )
    }

    override fun help(context: Context): String =
        "Save, restore, check, start, stop and tear down a whole system with RTSProfile files (XML or YAML), as " +
            "RTSystemEditor and rtshell (rtcryo, rtresurrect, rtcheck, rtstart, rtstop, rtteardown) do."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost profile save -o sys.xml" to
                "the running system, as rtcryo (add --connected for only connected components)",
            "rtcoord profile restore sys.xml" to
                "connections, configuration and rates back, as rtresurrect; once is enough",
            "rtcoord profile restore --create sys.xml" to
                "the same, creating missing components through their managers first",
            "rtcoord profile check sys.xml" to "print the differences, exit 1 when there are any, as rtcheck",
            "rtcoord profile start --dry-run sys.xml" to "the activation plan, as rtstart --dry-run",
        )
}
