package org.rtcoord.cli.serve

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** Headless Chromium, found on the `PATH` (or at `RTCOORD_CHROMIUM`), taking pictures of pages. */
internal object Chromium {
    private val NAMES = listOf("chromium", "chromium-browser", "google-chrome")

    /** The Chromium to run, or null when there is none. */
    fun executable(): Path? =
        System.getenv("RTCOORD_CHROMIUM")?.let(Path::of)?.takeIf(Files::isExecutable)
            ?: NAMES.firstNotNullOfOrNull { name ->
                System.getenv("PATH")
                    .orEmpty()
                    .split(File.pathSeparatorChar)
                    .filter { it.isNotEmpty() }
                    .map { Path.of(it, name) }
                    .firstOrNull { Files.isExecutable(it) }
            }

    /**
     * Flags every headless run takes, with [profile] as its user data: no GPU, no first-run pages, and no sandbox,
     * which containers and root seldom allow and the page, this program's own, does not need.
     */
    fun headlessFlags(profile: Path): List<String> =
        listOf(
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-dev-shm-usage",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-extensions",
            "--hide-scrollbars",
            "--user-data-dir=$profile",
        )

    /**
     * Saves a [width]×[height] PNG of the page at [url] to [file], once the page has had [budget] of virtual time to
     * draw itself; fails after [deadline].
     */
    fun screenshot(
        url: String,
        file: Path,
        width: Int = 1400,
        height: Int = 900,
        budget: Duration = 10.seconds,
        deadline: Duration = 120.seconds,
    ) {
        val executable =
            executable()
                ?: throw IllegalArgumentException(
                    "cannot take a picture: no chromium on the PATH (or set RTCOORD_CHROMIUM)"
                )
        val profile = Files.createTempDirectory("rtcoord-chromium")
        try {
            val target = file.toAbsolutePath()
            Files.deleteIfExists(target)
            val process =
                ProcessBuilder(
                        listOf(executable.toString()) +
                            headlessFlags(profile) +
                            listOf(
                                "--window-size=$width,$height",
                                "--virtual-time-budget=${budget.inWholeMilliseconds}",
                                "--screenshot=$target",
                                url,
                            )
                    )
                    .redirectErrorStream(true)
                    .redirectOutput(profile.resolve("chromium.log").toFile())
                    .start()
            if (!process.waitFor(deadline.inWholeMilliseconds, TimeUnit.MILLISECONDS)) {
                process.descendants().forEach { it.destroyForcibly() }
                process.destroyForcibly()
                throw IllegalArgumentException(
                    "cannot take a picture of $url: chromium did not finish within $deadline"
                )
            }
            require(Files.isRegularFile(target)) {
                "cannot take a picture of $url: chromium exited with ${process.exitValue()} and wrote no $file: " +
                    Files.readString(profile.resolve("chromium.log")).lines().lastOrNull { it.isNotBlank() }.orEmpty()
            }
        } finally {
            profile.toFile().deleteRecursively()
        }
    }
}
