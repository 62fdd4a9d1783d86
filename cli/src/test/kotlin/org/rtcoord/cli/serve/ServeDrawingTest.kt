package org.rtcoord.cli.serve

import java.nio.file.Paths
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.cli.Localisation
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Scenarios

/**
 * What the page draws, checked in Chromium against the tree: every connection an edge with a rendered box from the
 * first frame, every hosting an edge, no two node boxes overlapping, every port on its component, every drawn state the
 * tree's. On the localisation system, before and after the laser fails (the picture in docs/serve.png), and on a
 * pipeline of 200 components.
 */
class ServeDrawingTest {
    @Test
    fun `the localisation system is drawn true, before and after the laser fails`() {
        Localisation().use { localisation ->
            RtcTree(TreeConfig(listOf(localisation.naming.address), 3.seconds)).use { tree ->
                val script =
                    Paths.get(System.getProperty("rtcoord.root", ".."), "examples", "localisation.coord.kts")
                        .toAbsolutePath()
                val coordination = runBlocking {
                    ScriptHost().load(script, host = TreeConfig(listOf(localisation.naming.address), 3.seconds))
                }
                Coordinator(tree, coordination, EventOptions()).use { coordinator ->
                    runBlocking { coordinator.start() }
                    val service = runBlocking {
                        LiveService.start(
                            tree,
                            tree.node("/${localisation.naming.address}"),
                            coordinator,
                            EventOptions(),
                            ServeSettings(),
                        ) {}
                    }
                    service.use {
                        HeadlessChromium.start().use { browser ->
                            browser.navigate(service.url)
                            browser.await(
                                "the network drawn",
                                expression =
                                    "document.body.dataset.rendered === 'true' && rtcoord.cy.nodes('.component').length === 4",
                            )
                            assertDrawnTrue(browser, tree, "at first")
                            assertEquals(
                                "2 2",
                                browser
                                    .evaluate(
                                        "rtcoord.cy.edges('.data').length + ' ' + " +
                                            "rtcoord.cy.edges('.data').filter(e => e.source().hasClass('out') && e.target().hasClass('in')).length"
                                    )
                                    .jsonPrimitive
                                    .content,
                                "data connectors, each from an out-port to an in-port",
                            )

                            // Finding a component frames it and fades the rest; a port tells its data type.
                            val found =
                                browser
                                    .evaluate(
                                        "(() => { const find = document.getElementById('find'); find.value = 'laser_loc'; find.dispatchEvent(new Event('input')); " +
                                            "const found = rtcoord.cy.nodes('.match').map(n => n.id()).join(' '); find.value = ''; find.dispatchEvent(new Event('input')); " +
                                            "document.getElementById('zoom-fit').click(); return found; })()"
                                    )
                                    .jsonPrimitive
                                    .content
                            assertEquals(localisation.path("laser_localise0.rtc"), found, "the components found")
                            val laser = localisation.path("laser0.rtc")
                            assertEquals(
                                "IDL:RTC/TimedDoubleSeq:1.0",
                                browser
                                    .evaluate("rtcoord.cy.getElementById(${js("$laser#laser")}).data('dataType')")
                                    .jsonPrimitive
                                    .content,
                            )

                            // A paused timeline holds what comes meanwhile, and lists it on resuming.
                            browser.evaluate("document.getElementById('pause').click()")
                            localisation.system.component("laser0").fail()
                            val odo = localisation.path("odo_localise0.rtc")
                            await("the coordinator's reaction: odo_localise0 ACTIVE in the tree") {
                                tree.snapshot().components.any { entry ->
                                    entry.paths.any { it.toString() == odo } && entry.overallState.name == "ACTIVE"
                                }
                            }
                            browser.await(
                                "odo_localise0 drawn ACTIVE with its connectors",
                                expression =
                                    "rtcoord.cy.getElementById(${js(odo)}).data('state') === 'ACTIVE' && rtcoord.network.connections.some(c => c.target === ${js(odo)})",
                            )
                            assertDrawnTrue(browser, tree, "after the laser failed")
                            val errorListed =
                                "[...document.querySelectorAll('#timeline li')].some(li => li.dataset.source === ${js(laser)} && li.textContent.includes('-> ERROR'))"
                            assertEquals(
                                "false 1",
                                browser
                                    .evaluate("String($errorListed) + ' ' + Math.sign(rtcoord.held.length)")
                                    .jsonPrimitive
                                    .content,
                                "laser0's ERROR listed while paused, events held",
                            )
                            browser.evaluate("document.getElementById('pause').click()")
                            browser.await("laser0's ERROR listed on resuming", expression = errorListed)
                            browser.screenshot(Paths.get("target", "serve", "serve.png"))
                        }
                    }
                }
            }
        }
    }

    @Test
    fun `a pipeline of 200 components is drawn true`() {
        servedScenario({ Scenarios.pipeline(it, PIPELINE) }) { tree, service, browser ->
            val opened = TimeSource.Monotonic.markNow()
            browser.navigate(service.url)
            browser.await(
                "$PIPELINE components drawn",
                2.minutes,
                "document.body.dataset.rendered === 'true' && rtcoord.cy.nodes('.component').length === $PIPELINE",
            )
            val drawnIn = opened.elapsedNow()
            val checked = TimeSource.Monotonic.markNow()
            assertDrawnTrue(browser, tree, "the pipeline")
            assertEquals(
                PIPELINE - 1,
                browser.evaluate("rtcoord.cy.edges('.data').length").jsonPrimitive.content.toInt(),
                "connectors",
            )
            println(
                "serve: $PIPELINE-component pipeline drawn ${drawnIn.inWholeMilliseconds} ms after the page opened; " +
                    "checked in ${checked.elapsedNow().inWholeMilliseconds} ms"
            )
            browser.screenshot(Paths.get("target", "serve", "pipeline.png"))
        }
    }

    /** Asserts the drawing has no problem and its states are the tree's, once they have had time to agree. */
    private fun assertDrawnTrue(browser: HeadlessChromium, tree: RtcTree, moment: String) {
        var drawn = DrawnSystem.of(browser)
        // A state the tree noticed reaches the page a moment later: the drawing has a deadline to agree.
        runCatching {
            await("the drawn states to agree with the tree's $moment", 10.seconds) {
                DrawnSystem.stateDifferences(DrawnSystem.of(browser).also { drawn = it }, tree).isEmpty()
            }
        }
        assertEquals(emptyList<String>(), DrawnSystem.stateDifferences(drawn, tree), "states drawn $moment")
        assertEquals(emptyList<String>(), drawn.problems, "the drawing $moment")
    }

    private companion object {
        const val PIPELINE = 200

        /** [text] as a JavaScript string literal. */
        fun js(text: String): String = "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"
    }
}
