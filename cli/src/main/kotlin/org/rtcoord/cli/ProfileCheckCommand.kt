package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.choice
import org.rtcoord.LifeCycle
import org.rtcoord.cli.json.DifferenceJson

/** `rtcoord profile check`: rtcheck. */
class ProfileCheckCommand : ProfileFileCommand("check") {
    override fun help(context: Context): String =
        "Compare the running system with a profile: components present, their state, connections, configuration and " +
            "rates. Prints each difference and exits 1 when there is any."

    private val state by
        option("--state", help = "The state components should be in, any case (default: active, as rtcheck).")
            .choice("active", "inactive", "any", ignoreCase = true)
            .default("active")

    override suspend fun execute() {
        val profile = profile()
        val expected =
            when (state) {
                "active" -> LifeCycle.ACTIVE
                "inactive" -> LifeCycle.INACTIVE
                else -> null
            }
        val differences = refusing { profiles.check(profile, expected) }
        if (session.json) {
            echoJson(differences.map { DifferenceJson(it.subject, it.expected, it.actual) })
        } else {
            differences.forEach { echo(it.toString()) }
        }
        if (differences.isNotEmpty()) throw CommandFailed("${differences.size} difference(s) from the profile")
    }
}
