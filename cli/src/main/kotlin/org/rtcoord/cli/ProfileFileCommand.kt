package org.rtcoord.cli

import com.github.ajalt.clikt.parameters.arguments.argument
import java.nio.file.Paths
import org.rtcoord.RtcException
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles

/** A `profile` subcommand that reads a profile file (`-` for standard input) and works on the system. */
abstract class ProfileFileCommand(name: String) : TreeCommand(name) {
    private val file by
        argument("FILE", help = "An RTSProfile, XML or YAML (by its name or content); - for standard input.")

    /** The whole-system operations on the session's tree. */
    protected val profiles: SystemProfiles
        get() = SystemProfiles(tree)

    /** The profile, or a one-line error naming the file, line and problem. */
    protected fun profile(): RtsProfile =
        try {
            if (file == "-") {
                val text = System.`in`.bufferedReader().readText()
                RtsProfiles.parse(text, RtsProfiles.formatOf("-", text), "-")
            } else {
                RtsProfiles.read(Paths.get(file))
            }
        } catch (e: ProfileFormatException) {
            fail(e.message ?: e.reason, e)
        }

    /** Runs [work], turning a refused profile into a one-line error. */
    protected suspend fun <T> refusing(work: suspend () -> T): T =
        try {
            work()
        } catch (e: ProfileRefusedException) {
            fail("$file: nothing changed: ${e.reason}", e)
        } catch (e: RtcException) {
            fail("$file: ${e.message}", e)
        }
}
