package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.rtcoord.fixtures.Peers

/**
 * Where the things a run compares live: the checkout ([root], with the `rtcoord` launcher and the built CLI jar) and
 * the peers' virtual environment (rtshell's commands, a Python with rtctree).
 */
internal class Installation(val root: Path) {
    /** The `rtcoord` launcher users run. */
    val launcher: Path = root.resolve("rtcoord")

    /** The CLI jar the launcher runs, when it is built. */
    val cliJar: Path? =
        root.resolve("cli/target").takeIf(Files::isDirectory)?.let { target ->
            Files.list(target).use { files ->
                files.filter { it.fileName.toString().matches(Regex("rtcoord-cli-.*\\.jar")) }.findFirst().orElse(null)
            }
        }

    /** Why the CLI cannot be timed, or null when it can. The bench never builds it: `scripts/bench` does. */
    val cliMissing: String? =
        when {
            !Files.isExecutable(launcher) -> "no launcher at $launcher"
            cliJar == null -> "the CLI is not built (scripts/bench builds it; or run ./rtcoord --version)"
            else -> null
        }

    /** The peer executable [name] (`rtls`, `python`), or null when the peers are not installed. */
    fun peer(name: String): Path? = Peers.home.resolve("bin").resolve(name).takeIf(Files::isExecutable)

    /** Why the peer [name] cannot be timed. */
    fun peerMissing(name: String): String =
        "$name is not installed in ${Peers.home.resolve("bin")} (run scripts/peers.sh)"

    companion object {
        /** The checkout: `rtcoord.root` (set by the build and `scripts/bench`), else the working directory. */
        fun find(): Installation =
            Installation(
                Paths.get(System.getProperty("rtcoord.root") ?: System.getProperty("user.dir"))
                    .toAbsolutePath()
                    .normalize()
            )
    }
}
