package org.rtcoord.cli.serve

import java.net.InetSocketAddress
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.cli.Localisation
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.FluentLogSender

/**
 * A run recorded with `serve --record` while the laser fails, then replayed in Chromium: the replayed page at the end
 * of the recording draws the states the tree held when the recording ended, and at its start the states it began with;
 * the laser's error record is in the replayed timeline and marks its box from when it came.
 */
class ServeReplayTest {
    @TempDir lateinit var directory: Path

    @Test
    fun `a recorded run with a laser failure replays to the states the tree held`() {
        val file = directory.resolve("run.jsonl")
        val recorded: Map<String, String>
        val started: Map<String, String>
        val laser: String
        Localisation().use { localisation ->
            laser = localisation.path("laser0.rtc")
            RtcTree(TreeConfig(listOf(localisation.naming.address), 3.seconds)).use { tree ->
                val logs = tree.listenForLogs("127.0.0.1:0").port
                val top = runBlocking { tree.node("/${localisation.naming.address}") }
                runBlocking { LiveService.start(tree, top, null, EventOptions(), ServeSettings(record = file)) {} }
                    .use {
                        started = states(tree)
                        localisation.system.component("laser0").fail()
                        await("the tree to hold laser0 in ERROR") {
                            states(tree)[localisation.path("laser0.rtc")] == "ERROR"
                        }
                        await("the recording to hold laser0's ERROR") {
                            Files.readString(file).contains("\"new\":\"ERROR\"")
                        }
                        FluentLogSender(InetSocketAddress("127.0.0.1", logs), "manager_slave").use {
                            assertTrue(it.send("laser0", "ERROR", "scan failed"))
                        }
                        await("the recording to hold laser0's record") {
                            Files.readString(file).contains("\"message\":\"scan failed\"")
                        }
                        recorded = states(tree)
                    }
            }
        }
        val lines = Files.readAllLines(file)
        assertTrue(lines.first().startsWith("{\"kind\":\"snapshot\","), lines.first().take(80))
        assertTrue(
            lines.drop(1).all { it.startsWith("{\"kind\":\"event\",") || it.startsWith("{\"kind\":\"network\",") },
            "the lines after the snapshot",
        )

        runBlocking { LiveService.replay(Recording.read(file), ServeSettings()) }
            .use { service ->
                HeadlessChromium.start().use { browser ->
                    browser.navigate(service.url)
                    browser.await(
                        "the replay loaded",
                        expression = "rtcoord.replay !== null && document.body.dataset.rendered === 'true'",
                    )
                    assertEquals(started, DrawnSystem.of(browser).states, "the states drawn at the start of the replay")
                    browser.evaluate("seek(rtcoord.replay.end)")
                    val end = DrawnSystem.of(browser)
                    assertEquals(recorded, end.states, "the states drawn at the end of the replay")
                    assertEquals(emptyList<String>(), end.problems, "the replayed drawing")
                    assertEquals("true 1", records(browser, laser), "the laser's error at the end")
                    browser.evaluate("seek(rtcoord.replay.start)")
                    assertEquals(
                        started,
                        DrawnSystem.of(browser).states,
                        "the states drawn after going back to the start",
                    )
                    assertEquals("false 0", records(browser, laser), "the laser's error at the start")
                    assertEquals(
                        "replay",
                        browser.evaluate("document.getElementById('connection').textContent").jsonPrimitive.content,
                    )
                    // serve --replay --at: the page opens at that moment.
                    browser.navigate(service.url + "?at=" + Recording.read(file).length.inWholeMilliseconds / 1000.0)
                    browser.await(
                        "the replay loaded at its end",
                        expression = "rtcoord.replay !== null && rtcoord.replay.at === rtcoord.replay.end",
                    )
                    assertEquals(
                        recorded,
                        DrawnSystem.of(browser).states,
                        "the states drawn when the page opens at the end",
                    )
                }
            }
    }

    /** Whether [path]'s box is marked for an error, and how many log records the timeline holds. */
    private fun records(browser: HeadlessChromium, path: String): String =
        browser
            .evaluate(
                "rtcoord.cy.getElementById('$path').hasClass('logged-error') + ' ' + " +
                    "document.querySelectorAll('#timeline li[data-kind=record]').length"
            )
            .jsonPrimitive
            .content

    /** Each component's state as the tree's model holds it, by its naming path. */
    private fun states(tree: RtcTree): Map<String, String> =
        tree.snapshot().components.associate { it.path.toString() to it.overallState.name }
}
