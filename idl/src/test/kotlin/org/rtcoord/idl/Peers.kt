package org.rtcoord.idl

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.Assertions.fail
import org.junit.jupiter.api.Assumptions.assumeTrue

/**
 * The peer tools `scripts/peers.sh` installs. A missing tool fails the test in CI and skips it, with the command that
 * installs it, elsewhere.
 */
internal object Peers {
    private val home: Path =
        System.getenv("RTCOORD_PEERS")?.let { Paths.get(it) }
            ?: Paths.get(
                System.getenv("XDG_CACHE_HOME") ?: "${System.getProperty("user.home")}/.cache",
                "rtcoord",
                "peers",
            )

    fun tool(name: String): Path {
        val path = home.resolve("bin").resolve(name)
        if (!Files.isExecutable(path)) {
            val why = "$name is not installed in $home/bin: run scripts/peers.sh"
            if (System.getenv("CI") != null) fail<Unit>(why) else assumeTrue(false, why)
        }
        return path
    }

    /** The directory of Python package [name] in the peers' virtual environment. */
    fun sitePackage(name: String): Path {
        tool("python")
        val packages =
            Files.list(home.resolve("lib")).use { versions ->
                versions.map { it.resolve("site-packages").resolve(name) }.filter(Files::isDirectory).findFirst()
            }
        return packages.orElseThrow { AssertionError("$name is not installed in $home: run scripts/peers.sh") }
    }
}
