package org.rtcoord.cli.serve

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.Assertions.assertArrayEquals
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.Timeout
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.cli.Localisation
import org.rtcoord.cli.ok
import org.rtcoord.cli.runRtcoord

/** `serve --screenshot`: a picture taken headless, and the command ends, the event stream holding nothing up. */
class ServeScreenshotTest {
    @TempDir lateinit var directory: Path

    @Test
    @Timeout(value = 3, unit = TimeUnit.MINUTES)
    fun `serve --screenshot saves a picture of the page and exits`() {
        HeadlessChromium.assumeInstalled()
        Localisation().use { localisation ->
            val picture = directory.resolve("system.png")
            val printed = runRtcoord("serve", localisation.host, "--port", "0", "--screenshot", picture.toString()).ok()
            assertEquals("saved a picture of ${localisation.host} to $picture\n", printed)
            val png = Files.readAllBytes(picture)
            assertArrayEquals(
                byteArrayOf(0x89.toByte(), 'P'.code.toByte(), 'N'.code.toByte(), 'G'.code.toByte()),
                png.copyOf(4),
                "a PNG",
            )
            // 1400×900, as the PNG's header says.
            assertEquals(listOf(1400, 900), listOf(16, 20).map { java.nio.ByteBuffer.wrap(png, it, 4).int })
        }
    }
}
