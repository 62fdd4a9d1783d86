package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context

/** `rtcoord profile teardown`: rtteardown. */
class ProfileTeardownCommand : ProfileFileCommand("teardown") {
    override fun help(context: Context): String =
        "Remove the connections the profile names, whatever their connector ids are now."

    override suspend fun execute() {
        val removed = refusing { profiles.teardown(profile()) }
        if (session.json) echoJson(removed) else removed.forEach { confirm(it) }
    }
}
