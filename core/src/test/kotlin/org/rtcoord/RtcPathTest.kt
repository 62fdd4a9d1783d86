package org.rtcoord

import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNotEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.DynamicTest
import org.junit.jupiter.api.DynamicTest.dynamicTest
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestFactory
import org.rtcoord.fixtures.Peers

class RtcPathTest {
    private fun path(text: String, workingDirectory: String? = null) =
        RtcPath(text, workingDirectory?.let { RtcPath(it) })

    private fun bad(text: String, position: Int, reason: String, parse: () -> Any?) {
        val e = assertThrows(BadPathException::class.java) { parse() }
        assertEquals(text, e.subject)
        assertEquals(position, e.position)
        assertEquals("bad path: $reason (segment ${position + 1})", e.reason)
        assertEquals("$text: bad path: $reason (segment ${position + 1})", e.message)
    }

    @Test
    fun `the root`() {
        val root = path("/")
        assertEquals(RtcPath("/"), root)
        assertTrue(root.isRoot)
        assertTrue(root.isDirectory)
        assertNull(root.nameServer)
        assertEquals(emptyList<String>(), root.names)
        assertNull(root.port)
        assertNull(root.objectReference)
        assertNull(root.parent)
        assertEquals("/", root.name)
        assertEquals("", root.kind)
        assertEquals("/", root.toString())
        assertEquals(RtcPath("/"), path("/localhost/ctx/../.."))
    }

    private class NameServerCase(
        val text: String,
        val nameServer: String,
        val written: String,
        val isDirectory: Boolean,
    )

    @TestFactory
    fun `name servers normalise the port and keep the address as written`(): List<DynamicTest> =
        listOf(
                NameServerCase("/localhost", "localhost:2809", "localhost", false),
                NameServerCase("/localhost/", "localhost:2809", "localhost", true),
                NameServerCase("/localhost:2809", "localhost:2809", "localhost:2809", false),
                NameServerCase("/127.0.0.1:30000/", "127.0.0.1:30000", "127.0.0.1:30000", true),
                NameServerCase("/ns.example.org:02809", "ns.example.org:2809", "ns.example.org:02809", false),
            )
            .map { case ->
                dynamicTest(case.text) {
                    val server = path(case.text)
                    assertFalse(server.isRoot)
                    assertEquals(case.nameServer, server.nameServer)
                    assertEquals(case.written, server.name)
                    assertEquals(case.isDirectory, server.isDirectory)
                    assertEquals(emptyList<String>(), server.names)
                    assertNull(server.port)
                    assertEquals(RtcPath("/"), server.parent)
                    assertEquals("/${case.nameServer}", server.toString())
                }
            }

    @Test
    fun `host and port without a trailing slash is the name server, not a port of the host`() {
        val server = path("/localhost:2809")
        assertEquals("localhost:2809", server.nameServer)
        assertNull(server.port)
        assertEquals(emptyList<String>(), server.names)
        assertEquals(path("/localhost:2809/"), server)
        assertEquals(path("/localhost"), server)
        assertNotEquals(path("/localhost:2810"), server)
    }

    private class NodeCase(
        val text: String,
        val nameServer: String,
        val names: List<String>,
        val port: String?,
        val kind: String,
    )

    @TestFactory
    fun `contexts, objects and ports`(): List<DynamicTest> =
        listOf(
                NodeCase(
                    "/localhost/host.host_cxt/laser0.rtc",
                    "localhost:2809",
                    listOf("host.host_cxt", "laser0.rtc"),
                    null,
                    "rtc",
                ),
                NodeCase(
                    "/h:2810/a.host_cxt/b.cxt/c/d.rtc:out",
                    "h:2810",
                    listOf("a.host_cxt", "b.cxt", "c", "d.rtc"),
                    "out",
                    "rtc",
                ),
                NodeCase("/h/laser0.rtc:laser", "h:2809", listOf("laser0.rtc"), "laser", "rtc"),
                NodeCase("/h/comp.rtc:in.data", "h:2809", listOf("comp.rtc"), "in.data", "rtc"),
                NodeCase(
                    "/h/manager.mgr/slave/comp0.rtc",
                    "h:2809",
                    listOf("manager.mgr", "slave", "comp0.rtc"),
                    null,
                    "rtc",
                ),
                NodeCase("/h/manager.mgr", "h:2809", listOf("manager.mgr"), null, "mgr"),
                NodeCase("/h/odd #name (1).rtc:in-1", "h:2809", listOf("odd #name (1).rtc"), "in-1", "rtc"),
                NodeCase("/h/ctx/../x/./y.rtc", "h:2809", listOf("x", "y.rtc"), null, "rtc"),
            )
            .map { case ->
                dynamicTest(case.text) {
                    val node = path(case.text)
                    assertEquals(case.nameServer, node.nameServer)
                    assertEquals(case.names, node.names)
                    assertEquals(case.port, node.port)
                    assertEquals(case.kind, node.kind)
                    assertEquals(case.names.last(), node.name)
                    assertFalse(node.isDirectory)
                    assertNull(node.objectReference)
                }
            }

    @Test
    fun `a trailing slash marks a directory and names the same node`() {
        val directory = path("/localhost/ctx/")
        assertTrue(directory.isDirectory)
        assertFalse(path("/localhost/ctx").isDirectory)
        assertTrue(path("/localhost/ctx/.").isDirectory)
        assertTrue(path("/localhost/ctx/sub/..").isDirectory)
        assertEquals(path("/localhost/ctx"), directory)
        assertEquals(path("/localhost/ctx").hashCode(), directory.hashCode())
        assertEquals(0, path("/localhost/ctx").compareTo(directory))
        assertEquals("/localhost:2809/ctx", directory.toString())
        assertEquals(listOf("ctx"), directory.names)
    }

    @TestFactory
    fun `relative paths resolve against the working directory`(): List<DynamicTest> =
        listOf(
                Triple("/h/ctx", "laser0.rtc", "/h:2809/ctx/laser0.rtc"),
                Triple("/h/ctx/", "sub/laser0.rtc:in", "/h:2809/ctx/sub/laser0.rtc:in"),
                Triple("/h/ctx", "./x.rtc", "/h:2809/ctx/x.rtc"),
                Triple("/h/ctx", ".", "/h:2809/ctx"),
                Triple("/h/ctx", "../y.rtc", "/h:2809/y.rtc"),
                Triple("/h/ctx", "..", "/h:2809"),
                Triple("/h/ctx", "../..", "/"),
                Triple("/h/ctx", "../../other:1/z.rtc", "/other:1/z.rtc"),
                Triple("/h/ctx", "a/./b/../c.rtc:out", "/h:2809/ctx/a/c.rtc:out"),
                Triple("/h/ctx", "/abs/x.rtc", "/abs:2809/x.rtc"),
                Triple("/", "h/c.rtc", "/h:2809/c.rtc"),
                Triple("/", "h:3000", "/h:3000"),
            )
            .map { (workingDirectory, text, expected) ->
                dynamicTest("$text in $workingDirectory") {
                    assertEquals(expected, path(text, workingDirectory).toString())
                }
            }

    @Test
    fun `the working directory must be a node of the tree`() {
        assertThrows(IllegalArgumentException::class.java) { path("x.rtc", "/h/c.rtc:in") }
        assertThrows(IllegalArgumentException::class.java) { path("x.rtc", "corbaloc:iiop:h:1/manager") }
    }

    private class BadCase(val text: String, val position: Int, val reason: String, val workingDirectory: String? = null)

    @TestFactory
    fun `errors name the path, the segment and the reason`(): List<DynamicTest> =
        listOf(
                BadCase("", 0, "empty path"),
                BadCase("laser0.rtc", 0, "relative path without a working directory"),
                BadCase("//h", 0, "empty segment"),
                BadCase("/h//c.rtc", 1, "empty segment"),
                BadCase("/h/ctx//", 2, "empty segment"),
                BadCase("/h/x:1/c.rtc", 1, "port suffix only on the last segment"),
                BadCase("/h/c.rtc:in/.", 1, "port suffix only on the last segment"),
                BadCase("/h/c.rtc:in/", 1, "port suffix on a directory"),
                BadCase("/..", 0, "'..' above the root"),
                BadCase("/h/../..", 2, "'..' above the root"),
                BadCase("../x", 0, "'..' above the root", workingDirectory = "/"),
                BadCase("/h:99999", 0, "bad port '99999'"),
                BadCase("/h:0", 0, "bad port '0'"),
                BadCase("/h:http", 0, "bad port 'http'"),
                BadCase("/h:", 0, "bad port ''"),
                BadCase("/h:2809:in", 0, "bad port '2809:in'"),
                BadCase("/:2809", 0, "empty host in ':2809'"),
                BadCase("/h/:in", 1, "empty name"),
                BadCase("/h/..:in", 1, "'..' is not a name"),
                BadCase("/h/c.rtc:", 1, "empty port name"),
                BadCase("/h/c.rtc:a:b", 1, "bad port name 'a:b'"),
                BadCase("corbaloc:iiop:/NameService", 0, "empty name server address"),
                BadCase("corbaloc:iiop:h:99999/NameService", 0, "bad port '99999'"),
                BadCase("corbaloc:iiop:h:1", 0, "corbaloc without an object key"),
                BadCase("corbaloc:iiop:h:1/", 0, "corbaloc without an object key"),
                BadCase("corbaloc:iiop:h:1/NameService#", 1, "empty segment"),
                BadCase("corbaloc:iiop:h:1/NameService#ctx//x.rtc", 2, "empty segment"),
                BadCase("corbaloc:iiop:h:1/NameService#a:1/x.rtc", 1, "port suffix only on the last segment"),
                BadCase("corbaloc:iiop:h:1/NameService#../..", 2, "'..' above the root"),
                BadCase("corbaloc:iiop:h:1/manager#x", 0, "'#' follows only a corbaloc:iiop:host:port/NameService"),
            )
            .map { case ->
                dynamicTest("'${case.text}'") {
                    bad(case.text, case.position, case.reason) { path(case.text, case.workingDirectory) }
                }
            }

    @TestFactory
    fun `a corbaloc NameService address is the name server`(): List<DynamicTest> =
        listOf(
                "corbaloc:iiop:h:1/NameService" to "/h:1",
                "corbaloc::h:1/NameService" to "/h:1",
                "corbaloc:iiop:h/NameService" to "/h:2809",
                "corbaloc:iiop:1.2@h:2810/NameService" to "/h:2810",
                "CORBALOC:IIOP:h:1/NameService" to "/h:1",
                "/corbaloc:iiop:h:1/NameService" to "/h:1",
            )
            .map { (text, expected) ->
                dynamicTest(text) {
                    val server = path(text)
                    assertEquals(path(expected), server)
                    assertEquals(expected, server.toString())
                    assertEquals(emptyList<String>(), server.names)
                    assertNull(server.objectReference)
                }
            }

    @Test
    fun `a corbaloc NameService address continues after a hash`() {
        val port = path("corbaloc:iiop:h:1/NameService#ctx/name.rtc:port")
        assertEquals("h:1", port.nameServer)
        assertEquals(listOf("ctx", "name.rtc"), port.names)
        assertEquals("port", port.port)
        assertEquals(path("/h:1/ctx/name.rtc:port"), port)
        assertTrue(path("corbaloc::h:1/NameService#ctx/").isDirectory)
        assertEquals(path("/h:1/b.rtc"), path("corbaloc::h:1/NameService#a/../b.rtc"))
    }

    @TestFactory
    fun `any other corbaloc is a direct object reference`(): List<DynamicTest> =
        listOf(
                "corbaloc:iiop:h:2810/manager",
                "corbaloc:iiop:h:1,iiop:g:1/NameService",
                "corbaloc:rir:/NameService",
                "corbaloc:iiop:h:1/NameService/x",
            )
            .map { text ->
                dynamicTest(text) {
                    val reference = path(text)
                    assertEquals(text, reference.objectReference)
                    assertNull(reference.nameServer)
                    assertFalse(reference.isRoot)
                    assertEquals(emptyList<String>(), reference.names)
                    assertNull(reference.parent)
                    assertEquals(text, reference.name)
                    assertEquals(text, reference.toString())
                    assertTrue(reference.startsWith(reference))
                    assertFalse(reference.startsWith(RtcPath("/")))
                    bad("$text/x", 1, "nothing below an object reference") { reference.child("x") }
                    bad("$text:in", 0, "a port only on a named object") { reference.withPort("in") }
                }
            }

    @TestFactory
    fun `the canonical text parses back to the same path`(): List<DynamicTest> =
        listOf(
                "/",
                "/localhost",
                "/localhost:2810/",
                "/h/host.host_cxt/laser0.rtc",
                "/h/comp.rtc:in.data",
                "/h/m.mgr/slave/c.rtc",
                "corbaloc::h:1/NameService#ctx/c.rtc:in",
                "corbaloc:iiop:h:2810/manager",
            )
            .map { text ->
                dynamicTest(text) {
                    val parsed = path(text)
                    assertEquals(parsed, RtcPath(parsed.toString()))
                    assertEquals(parsed.toString(), RtcPath(parsed.toString()).toString())
                }
            }

    @Test
    fun `parent goes up to the root and child comes back down`() {
        val port = path("/h/ctx/c.rtc:in")
        val ancestors = generateSequence(port) { it.parent }.map { it.toString() }.toList()
        assertEquals(listOf("/h:2809/ctx/c.rtc:in", "/h:2809/ctx/c.rtc", "/h:2809/ctx", "/h:2809", "/"), ancestors)
        assertEquals(port, RtcPath("/").child("h").child("ctx").child("c.rtc").withPort("in"))
        assertEquals(path("/h:1"), RtcPath("/").child("h:1"))
        assertEquals("h", RtcPath("/").child("h").name)
        assertEquals(path("/h/ctx/c.rtc"), port.withPort(null))
        assertEquals(path("/h/c.rtc:out"), path("/h/c.rtc:in").withPort("out"))
    }

    @Test
    fun `child and withPort reject what the grammar rejects`() {
        val server = path("/h")
        bad("/h:2809/a/b", 1, "'/' in a name") { server.child("a/b") }
        bad("/h:2809/a:b", 1, "':' in a name") { server.child("a:b") }
        bad("/h:2809/..", 1, "'..' is not a name") { server.child("..") }
        bad("/h:2809/", 1, "empty name") { server.child("") }
        bad("/..", 0, "not a name server address") { RtcPath("/").child("..") }
        bad("/h:99999", 0, "bad port '99999'") { RtcPath("/").child("h:99999") }
        bad("/h:2809/c.rtc:in/x", 2, "nothing below a port") { path("/h/c.rtc:in").child("x") }
        bad("/:in", 0, "a port only on a named object") { RtcPath("/").withPort("in") }
        bad("/h:2809:in", 0, "a port only on a named object") { server.withPort("in") }
        bad("/h:2809/c.rtc:a:b", 1, "bad port name 'a:b'") { path("/h/c.rtc").withPort("a:b") }
        bad("/h:2809/c.rtc:", 1, "empty port name") { path("/h/c.rtc").withPort("") }
    }

    @Test
    fun `startsWith compares whole segments and the normalised name server`() {
        val port = path("/h/ctx/c.rtc:in")
        listOf("/h:2809/ctx/c.rtc:in", "/h/ctx/c.rtc", "/h/ctx/", "/h:2809", "/").forEach {
            assertTrue(port.startsWith(path(it)), it)
        }
        listOf("/h/ct", "/h/ctx/c.rtc:out", "/g/ctx", "/h:2810", "/h/ctx/c.rtc/x").forEach {
            assertFalse(port.startsWith(path(it)), it)
        }
        assertFalse(path("/h/ctx").startsWith(path("/h/ctx/c.rtc")))
        assertFalse(RtcPath("/").startsWith(path("/h")))
    }

    @TestFactory
    fun `the kind follows the last dot of the last name`(): List<DynamicTest> =
        listOf(
                "/h/a.b.rtc" to "rtc",
                "/h/host.host_cxt" to "host_cxt",
                "/h/m.mgr" to "mgr",
                "/h/foo" to "",
                "/h/foo." to "",
                "/h/.rtc" to "rtc",
                "/h/c.rtc:in.data" to "rtc",
                "/h" to "",
                "/" to "",
            )
            .map { (text, kind) -> dynamicTest(text) { assertEquals(kind, path(text).kind) } }

    @Test
    fun `paths sort in tree order`() {
        val sorted =
            listOf(
                    "/",
                    "/a",
                    "/a/x",
                    "/a/x/c.rtc",
                    "/a/x/c.rtc:in",
                    "/a/x/c.rtc:out",
                    "/a/x.rtc",
                    "/a:3000",
                    "/b",
                    "corbaloc:iiop:h:1/manager",
                )
                .map { path(it) }
        assertEquals(sorted, sorted.reversed().sorted())
        assertEquals(sorted, sorted.shuffled(java.util.Random(7)).sorted())
    }

    @Test
    fun `nameServer accepts host, host and port, and corbaloc addresses`() {
        assertEquals(path("/localhost:2809"), nameServerPath("localhost"))
        assertEquals("localhost", nameServerPath("localhost").name)
        assertEquals(path("/h:1"), nameServerPath("h:1"))
        assertEquals(path("/h:1"), nameServerPath("corbaloc:iiop:h:1"))
        assertEquals(path("/h:1"), nameServerPath("corbaloc:iiop:h:1/NameService"))
        bad("h/x", 0, "not a name server address") { nameServerPath("h/x") }
        bad("corbaloc:iiop:h:1/manager", 0, "not a name server address") { nameServerPath("corbaloc:iiop:h:1/manager") }
        bad("h:99999", 0, "bad port '99999'") { nameServerPath("h:99999") }
        bad("", 0, "empty name server address") { nameServerPath("") }
    }

    /** How rtshell's commands read each `(working directory, path)`, one line each (see the script). */
    private fun rtshellView(cases: List<Pair<String, String>>): List<String> {
        val script = Paths.get(javaClass.getResource("/rtshell_parse_path.py")!!.toURI())
        val python =
            ProcessBuilder(Peers.require("python").toString(), script.toString())
                .redirectError(ProcessBuilder.Redirect.INHERIT)
                .start()
        python.outputStream.bufferedWriter().use { input ->
            cases.forEach { (cwd, text) -> input.write("$cwd\t$text\n") }
        }
        val lines = python.inputStream.bufferedReader().readLines()
        assertTrue(python.waitFor(60, TimeUnit.SECONDS), "rtshell's parser did not finish")
        assertEquals(0, python.exitValue())
        return lines
    }

    /** This path in the script's format: rtctree's list of names, the name server as written. */
    private fun RtcPath.asRtctree(): String {
        val segments = generateSequence(withPort(null)) { it.parent }.map { it.name }.toList().reversed()
        return (listOf("ok", port?.let { ":$it" } ?: "") + segments).joinToString("\t")
    }

    @Test
    fun `rtshell reads the paths we accept the same way, except the name server with a port`() {
        val accepted =
            listOf(
                "/" to "/",
                "/" to "/localhost",
                "/" to "/localhost/",
                "/" to "/127.0.0.1:2810/",
                "/" to "/localhost/host.host_cxt/laser0.rtc",
                "/" to "/localhost/laser0.rtc:laser",
                "/" to "/localhost/c.rtc:in.data",
                "/" to "/localhost/m.mgr/slave/c.rtc",
                "/" to "/h/a.b.rtc",
                "/" to "/h/ctx/../c.rtc",
                "/" to "localhost/c.rtc",
                "/localhost/ctx" to "laser0.rtc",
                "/localhost/ctx" to "../x.rtc:out",
                "/localhost/ctx/" to "./sub/",
                "/localhost/ctx" to "..",
                "/localhost" to "../other:1234/ns.rtc",
            )
        val fixed = "/" to "/localhost:2809"
        val rejectedByBoth = "/" to "/h/c.rtc:a:b"
        val view = rtshellView(accepted + fixed + rejectedByBoth)

        accepted.forEachIndexed { i, (cwd, text) ->
            // rtctree keeps an empty last name for a trailing slash.
            assertEquals(path(text, cwd).asRtctree(), view[i].removeSuffix("\t"), "$text in $cwd")
        }
        assertEquals("ok\t:2809\t/\tlocalhost", view[accepted.size], "rtshell reads a port of the host")
        assertEquals("/localhost:2809", path(fixed.second).toString())
        assertEquals("error\tBadPathError", view[accepted.size + 1])
        assertThrows(BadPathException::class.java) { path(rejectedByBoth.second) }
    }
}
