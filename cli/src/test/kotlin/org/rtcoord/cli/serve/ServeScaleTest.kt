package org.rtcoord.cli.serve

import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.serialization.json.double
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.condition.EnabledIfSystemProperty
import org.rtcoord.runtime.Scenarios

/**
 * A thousand components: the page draws them all and stays responsive. On request (`-Drtcoord.scale=true`), as the soak
 * is: it measures more than it checks, and its thousand components and browser cost the default build half a minute,
 * where [ServeDrawingTest]'s 200 components already check the drawing at size.
 */
@EnabledIfSystemProperty(named = "rtcoord.scale", matches = "true")
class ServeScaleTest {
    @Test
    fun `a thousand components render and the page stays responsive`() {
        servedScenario({ Scenarios.scale(it, COUNT) }) { _, service, browser ->
            val opened = TimeSource.Monotonic.markNow()
            browser.navigate(service.url)
            browser.await(
                "$COUNT components drawn",
                5.minutes,
                "document.body.dataset.rendered === 'true' && rtcoord.cy.nodes('.component').length === $COUNT",
            )
            val firstRender = browser.evaluate("rtcoord.renderedAt").jsonPrimitive.double
            val seen = opened.elapsedNow()
            browser.screenshot(java.nio.file.Paths.get("target", "serve", "scale.png"))

            // A click shows a component's details; zooming answers at once.
            val asked = TimeSource.Monotonic.markNow()
            browser.evaluate("document.querySelector('#components li[data-component\$=\"/relay1.rtc\"]').click()")
            browser.await(
                "relay1's details",
                60.seconds,
                "document.querySelector('[data-details\$=\"/relay1.rtc\"]') !== null",
            )
            val details = asked.elapsedNow()
            val roundTrips =
                (1..10).map {
                    val mark = TimeSource.Monotonic.markNow()
                    browser.evaluate("rtcoord.cy.zoom(rtcoord.cy.zoom() * 1.1); rtcoord.cy.nodes().length")
                    mark.elapsedNow().inWholeMilliseconds
                }
            println(
                "serve: $COUNT components: first render ${firstRender.toLong()} ms after the page started loading " +
                    "(${seen.inWholeMilliseconds} ms as the test saw it); details on click in ${details.inWholeMilliseconds} ms; " +
                    "zoom round trips ${roundTrips.sorted()} ms"
            )
            assertTrue(roundTrips.max() < 5_000, "the page took ${roundTrips.max()} ms to answer a zoom")
        }
    }

    private companion object {
        const val COUNT = 1000
    }
}
