package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.cli.json.RestoreJson

/** `rtcoord profile restore`: rtresurrect, checked before anything changes. */
class ProfileRestoreCommand : ProfileFileCommand("restore") {
    override fun help(context: Context): String =
        "Restore a profile onto the running system: make its connections (identical ones are kept), write its " +
            "configuration sets and activate its active set, set execution context rates. Everything is checked first: " +
            "a missing required component, port or incompatible connection changes nothing. A value outside the constraint " +
            "its component declares is written, as rtresurrect and OpenRTM-aist write it, with a warning; a value the " +
            "component holds is not written, so a profile always restores onto the system it was saved from."

    private val create by
        option(
                "--create",
                help =
                    "First create missing components through the manager of their naming context (or the nearest above it), " +
                        "by the type in their component id; a restore refused after that deletes them again.",
            )
            .flag()

    private val strict by
        option(
                "--strict",
                help =
                    "Refuse the restore, changing nothing, when it would write a value outside the constraint its component " +
                        "declares in __constraints__ (without it, a warning names each such value).",
            )
            .flag()

    override suspend fun execute() {
        val profile = profile()
        val report = refusing { profiles.restore(profile, createMissing = create, strict = strict) }
        report.warnings.forEach { echo("rtcoord: warning: $it", err = true) }
        if (session.json) {
            echoJson(RestoreJson(report.done, report.kept, report.missingOptional, report.created, report.warnings))
            return
        }
        report.done.forEach { confirm(it) }
        report.missingOptional.forEach { echo("not running (optional): $it", err = true) }
        if (report.done.isEmpty()) confirm("nothing to change (${report.kept.size} connections already there)")
    }
}
