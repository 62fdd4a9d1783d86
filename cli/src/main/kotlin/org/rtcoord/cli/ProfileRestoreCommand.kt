package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option

/** `rtcoord profile restore`: rtresurrect, checked before anything changes. */
class ProfileRestoreCommand : ProfileFileCommand("restore") {
    override fun help(context: Context): String =
        "Restore a profile onto the running system: make its connections (identical ones are kept), write its " +
            "configuration sets and activate its active set, set execution context rates. Everything is checked first: " +
            "a missing required component, port or incompatible connection, or a value out of range, changes nothing."

    private val create by option(
        "--create",
        help = "First create missing components through the manager of their naming context (or the nearest above it), " +
            "by the type in their component id; a restore refused after that deletes them again.",
    ).flag()

    override suspend fun execute() {
        val profile = profile()
        val report = refusing { profiles.restore(profile, createMissing = create) }
        if (session.json) {
            echoJson(mapOf("done" to report.done, "kept" to report.kept, "missingOptional" to report.missingOptional, "created" to report.created))
            return
        }
        report.done.forEach { confirm(it) }
        report.missingOptional.forEach { echo("not running (optional): $it", err = true) }
        if (report.done.isEmpty()) confirm("nothing to change (${report.kept.size} connections already there)")
    }
}
