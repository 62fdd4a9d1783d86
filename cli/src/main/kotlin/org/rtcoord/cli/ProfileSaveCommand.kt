package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.optional
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import java.nio.file.Files
import java.nio.file.Paths
import org.rtcoord.RtcPath
import org.rtcoord.nameServerPath
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles

/** `rtcoord profile save`: rtcryo. */
class ProfileSaveCommand : TreeCommand("save") {
    override fun help(context: Context): String =
        "Save the running system below PATH (every name server by default) as an RTSProfile: components, ports, " +
            "configuration sets and the active set, execution contexts and rates, connections and their properties."

    private val path by argument("PATH", help = "Where to start (default: every name server).").optional()

    private val output by option("-o", "--output", metavar = "FILE", help = "Write to FILE (default: standard output).")

    private val yaml by
        option("-y", "--yaml", help = "YAML instead of XML (also chosen by a .yaml output name).").flag()

    private val connected by option("--connected", help = "Only components with connections, as rtcryo.").flag()

    private val systemId by
        option("--id", metavar = "ID", help = "The system's id.").default("RTSystem:rtcoord:RTSystem:0")

    private val abstract by option("--abstract", metavar = "TEXT", help = "A description of the system.").default("")

    override suspend fun execute() {
        val below =
            path?.let { pathOf(it) } ?: session.nameServers.singleOrNull()?.let { nameServerPath(it) } ?: RtcPath("/")
        val profile = SystemProfiles(tree).save(below, connected, systemId, abstract)
        val format =
            if (yaml || output?.let { RtsProfiles.formatOf(it, "") } == ProfileFormat.YAML) ProfileFormat.YAML
            else ProfileFormat.XML
        val text = RtsProfiles.write(profile, format)
        val file = output
        if (file == null || file == "-") echo(text, trailingNewline = false)
        else Files.writeString(Paths.get(file), text)
    }
}
