package org.rtcoord.cli.serve

import java.net.InetAddress
import java.net.InetSocketAddress
import java.nio.file.Path
import java.nio.file.Paths
import java.time.Instant
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.long
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.cli.Localisation
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.FluentLogSender

/**
 * The page in a real browser (headless Chromium) on the paper's localisation system coordinated by
 * `examples/localisation.coord.kts`: drawn whole, then live as the laser fails and the coordinator reacts, and through
 * a restart of the server.
 */
class ServeBrowserTest {
    private val localisation = Localisation()
    private val nameServer = "/${localisation.naming.address}"
    private val tree = RtcTree(TreeConfig(listOf(localisation.naming.address), 3.seconds))
    private val closing = mutableListOf<AutoCloseable>()

    @AfterEach
    fun stop() {
        closing.asReversed().forEach { runCatching { it.close() } }
        tree.close()
        localisation.close()
    }

    private fun <T : AutoCloseable> T.closedAfter(): T = also { closing += it }

    private fun coordinator(): Coordinator = runBlocking {
        val script =
            Paths.get(System.getProperty("rtcoord.root", ".."), "examples", "localisation.coord.kts").toAbsolutePath()
        val coordination = ScriptHost().load(script, host = TreeConfig(listOf(localisation.naming.address), 3.seconds))
        Coordinator(tree, coordination, EventOptions()).closedAfter().also { it.start() }
    }

    private fun serve(coordinator: Coordinator?, port: Int = 0): LiveService = runBlocking {
        LiveService.start(tree, tree.node(nameServer), coordinator, EventOptions(), ServeSettings(port = port)) {}
    }

    /** Headless Chromium on [service]'s page, once the page has drawn the four components. */
    private fun drawn(service: LiveService): HeadlessChromium =
        HeadlessChromium.start().closedAfter().also { browser ->
            browser.navigate(service.url)
            browser.await(
                "the network drawn",
                expression = "document.body.dataset.rendered === 'true' && rtcoord.cy.nodes('.component').length === 4",
            )
        }

    private val components = listOf("laser0", "gyro0", "odometry0", "laser_localise0")

    @Test
    fun `the page draws the system, then shows the laser's failure and the coordinator's reaction without a reload`() {
        val coordinator = coordinator()
        val service = serve(coordinator).closedAfter()
        val browser = drawn(service)
        browser.screenshot(SCREENSHOTS.resolve("localisation.png"))

        // Every component is in the graph, inside the view, in its state, and listed with it.
        for (name in components) {
            val path = localisation.path("$name.rtc")
            val drawn =
                browser
                    .evaluate(
                        """(() => { const n = rtcoord.cy.getElementById(${js(path)}); const b = n.renderedBoundingBox();
                   const li = document.querySelector('#components li[data-component="' + CSS.escape(${js(path)}) + '"]');
                   return n.data('state') + ' ' + (b.x1 >= 0 && b.y1 >= 0 && b.x2 <= rtcoord.cy.width() && b.y2 <= rtcoord.cy.height()) + ' ' + (li && li.dataset.state); })()"""
                    )
                    .jsonPrimitive
                    .content
            assertEquals("ACTIVE true ACTIVE", drawn, name)
        }
        val loadedAt = browser.evaluate("rtcoord.loadedAt").jsonPrimitive.long

        val laser = localisation.path("laser0.rtc")
        val failedAt = System.currentTimeMillis()
        localisation.system.component("laser0").fail()
        browser.await(
            "laser0 shown in ERROR",
            expression =
                "rtcoord.shown[${js(laser)}] && rtcoord.shown[${js(laser)}].noticedAt && " +
                    "['ERROR', 'INACTIVE'].includes(rtcoord.shown[${js(laser)}].state)",
        )
        // The page's clock and the tree's are the same machine's: how long from the tree noticing it to the page
        // showing it.
        val shownAt = browser.evaluate("rtcoord.shown[${js(laser)}].at").jsonPrimitive.long
        val noticedAt = browser.evaluate("rtcoord.shown[${js(laser)}].noticedAt").jsonPrimitive.long
        browser.await(
            "the timeline to list laser0's ERROR",
            expression =
                "[...document.querySelectorAll('#timeline li[data-kind=state]')]" +
                    ".some(li => li.dataset.source === ${js(laser)} && li.textContent.includes('-> ERROR'))",
        )

        // The coordinator's rule on the laser fired, the page says so; its reaction reshapes the graph.
        val rule = coordinator.rules.single { it.description.startsWith("laser0.rtc") }.description
        browser.await(
            "the rule's firing shown",
            expression = "document.querySelector('.rule[data-firings=\"1\"]') !== null",
        )
        val firedAt =
            browser.evaluate("Date.parse(rtcoord.coordinatorShownAt[${js(rule)}].lastFired)").jsonPrimitive.long
        val ruleShownAt = browser.evaluate("rtcoord.coordinatorShownAt[${js(rule)}].at").jsonPrimitive.long
        val odo = localisation.path("odo_localise0.rtc")
        browser.await(
            "odo_localise0 drawn ACTIVE",
            expression = "rtcoord.cy.getElementById(${js(odo)}).data('state') === 'ACTIVE'",
        )
        browser.await(
            "laser_localise0 drawn INACTIVE",
            expression =
                "rtcoord.cy.getElementById(${js(localisation.path("laser_localise0.rtc"))}).data('state') === 'INACTIVE'",
        )
        browser.screenshot(SCREENSHOTS.resolve("localisation-recovered.png"))

        println(
            "serve: laser0 ERROR shown ${shownAt - noticedAt} ms after the tree noticed it, ${shownAt - failedAt} ms after it failed; " +
                "rule firing shown ${ruleShownAt - firedAt} ms after it fired"
        )
        assertTrue(shownAt - noticedAt < 1000, "ERROR shown ${shownAt - noticedAt} ms after it was noticed")
        assertTrue(ruleShownAt - firedAt < 1000, "firing shown ${ruleShownAt - firedAt} ms after it fired")
        assertEquals(loadedAt, browser.evaluate("rtcoord.loadedAt").jsonPrimitive.long, "the page was reloaded")
        assertEquals("1", browser.evaluate("String(rtcoord.snapshots)").jsonPrimitive.content, "the page reconnected")
    }

    @Test
    fun `a page opened after states changed draws every component in the state the tree holds`() {
        val service = serve(null).closedAfter()
        // Changed while the server follows the system, before any page is open: the page must not start from an old
        // picture.
        runBlocking { tree.component(localisation.path("gyro0.rtc")).deactivate() }
        localisation.system.component("laser0").fail()
        val expected =
            mapOf("gyro0" to "INACTIVE", "laser0" to "ERROR", "odometry0" to "ACTIVE", "laser_localise0" to "ACTIVE")
        await("the tree to hold both changes") {
            tree.snapshot().components.associate { it.node.name.removeSuffix(".rtc") to it.overallState.name } ==
                expected
        }

        val browser = drawn(service)
        for (entry in tree.snapshot().components) {
            val drawn =
                browser
                    .evaluate("rtcoord.cy.getElementById(${js(entry.path.toString())}).data('state')")
                    .jsonPrimitive
                    .content
            assertEquals(entry.overallState.name, drawn, entry.path.toString())
            assertEquals(runBlocking { entry.node.state() }.name, drawn, "${entry.path} as read now")
        }
    }

    @Test
    fun `the page reconnects to a restarted server and follows components appearing and vanishing`() {
        var service = serve(null)
        val port = service.url.substringAfterLast(':').trimEnd('/').toInt()
        val browser = drawn(service)
        val loadedAt = browser.evaluate("rtcoord.loadedAt").jsonPrimitive.long

        service.close()
        browser.await(
            "the page to notice",
            expression = "document.getElementById('connection').dataset.connected === 'false'",
        )
        service = serve(null, port).closedAfter()
        browser.await(
            "the page to reconnect",
            expression =
                "rtcoord.snapshots === 2 && document.getElementById('connection').dataset.connected === 'true'",
        )

        val manager = runBlocking { tree.manager(localisation.path("manager.mgr")) }
        runBlocking { manager.create("odo_localise") }
        val odo = localisation.path("odo_localise0.rtc")
        browser.await("odo_localise0 to appear", expression = "rtcoord.cy.getElementById(${js(odo)}).nonempty()")
        runBlocking { manager.delete("odo_localise0") }
        browser.await("odo_localise0 to vanish", expression = "rtcoord.cy.getElementById(${js(odo)}).empty()")
        assertEquals(loadedAt, browser.evaluate("rtcoord.loadedAt").jsonPrimitive.long, "the page was reloaded")
    }

    @Test
    fun `the page shows the components' log records, filters them by level and component, marks errors, exports CSV`() {
        val port = tree.listenForLogs("127.0.0.1:0").port
        val service = serve(null).closedAfter()
        val browser = drawn(service)
        val laser = localisation.path("laser0.rtc")
        val gyro = localisation.path("gyro0.rtc")
        val failed = "scan failed, \"range\" 0\nat beam 3"
        FluentLogSender(InetSocketAddress("127.0.0.1", port), "manager_slave", "rtclog").closedAfter().apply {
            assertTrue(send("laser0", "INFO", "scan started"))
            assertTrue(send("laser0", "ERROR", failed))
            assertTrue(send("gyro0", "WARN", "drift high"))
        }
        browser.await(
            "the three records in the timeline",
            expression = "document.querySelectorAll('#timeline li[data-kind=record]').length === 3",
        )
        assertEquals(
            "ERROR $laser  laser0: $failed",
            browser
                .evaluate(
                    "[...document.querySelectorAll('#timeline li[data-kind=record]')].find(li => li.dataset.level === 'ERROR')" +
                        ".textContent.replace(/^\\S+record/, '')"
                )
                .jsonPrimitive
                .content,
            "the error's line, after its time",
        )

        // The error marks the laser's box and its line in the list, the warning marks nothing.
        assertEquals(
            "true false true",
            browser
                .evaluate(
                    "rtcoord.cy.getElementById(${js(laser)}).hasClass('logged-error') + ' ' + " +
                        "rtcoord.cy.getElementById(${js(gyro)}).hasClass('logged-error') + ' ' + " +
                        "document.querySelector('#components li[data-component=\"' + CSS.escape(${js(laser)}) + " +
                        "'\"] .logged-error').title.includes('ERROR at ')"
                )
                .jsonPrimitive
                .content,
        )
        browser.screenshot(SCREENSHOTS.resolve("localisation-records.png"))

        // WARN and above: the INFO record is hidden, the others shown; the CSV has the two shown, oldest first.
        browser.evaluate(
            "(() => { const s = document.getElementById('level'); s.value = 'WARN'; s.dispatchEvent(new Event('change')); })()"
        )
        assertEquals(
            "INFO:true ERROR:false WARN:false",
            browser
                .evaluate(
                    "[...document.querySelectorAll('#timeline li[data-kind=record]')].reverse()" +
                        ".map(li => li.dataset.level + ':' + li.hidden).join(' ')"
                )
                .jsonPrimitive
                .content,
        )
        val pid = ProcessHandle.current().pid()
        val host = InetAddress.getLocalHost().hostName
        assertEquals(
            listOf(
                "level,path,logger,message,pid,host,manager",
                "ERROR,$laser,laser0,\"scan failed, \"\"range\"\" 0\nat beam 3\",$pid,$host,manager_slave",
                "WARN,$gyro,gyro0,drift high,$pid,$host,manager_slave",
            ),
            csvWithoutTimes(browser),
        )

        // The laser selected and the timeline narrowed to it: the gyro's warning goes.
        browser.evaluate(
            "document.querySelector('#components li[data-component=\"' + CSS.escape(${js(laser)}) + '\"]').click()"
        )
        browser.evaluate(
            "(() => { const c = document.getElementById('only-selected'); c.checked = true; c.dispatchEvent(new Event('change')); })()"
        )
        assertEquals(listOf("level,path,logger,message,pid,host,manager"), csvWithoutTimes(browser).take(1))
        assertEquals(listOf("ERROR"), csvWithoutTimes(browser).drop(1).map { it.substringBefore(',') })
        browser.await(
            "the laser's panel to say its last error",
            expression =
                "document.querySelector('[data-last-error]').textContent.startsWith('last ERROR at ') && " +
                    "document.querySelector('[data-last-error]').textContent.includes('(laser0): scan failed')",
        )
    }

    /**
     * The page's CSV of the records it shows, each line without its first field, which must be a time (`time` on the
     * header); a record's message may hold a line break, inside quotes.
     */
    private fun csvWithoutTimes(browser: HeadlessChromium): List<String> {
        val csv = browser.evaluate("rtcoord.recordsCsv()").jsonPrimitive.content
        assertTrue(csv.endsWith("\r\n"), csv)
        return csv.removeSuffix("\r\n").split("\r\n").mapIndexed { i, line ->
            val time = line.substringBefore(',')
            if (i == 0) assertEquals("time", time) else Instant.parse(time)
            line.substringAfter(',')
        }
    }

    private companion object {
        val SCREENSHOTS: Path = Paths.get("target", "serve")

        /** [text] as a JavaScript string literal. */
        fun js(text: String): String = "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"
    }
}
