package org.rtcoord.cli

import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.MethodSource

/**
 * Every command against an unknown path, a path of the wrong kind and an unreachable name server:
 * exit status 1, nothing on stdout, one `rtcoord: <what>: <why>` line on stderr.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class BadInputTest {
    private val localisation = Localisation()

    @AfterAll
    fun stop() = localisation.close()

    /** A command, how it takes a path, and a path of the wrong kind for it with the reason it gives. */
    class Case(
        private val name: String,
        val arguments: (path: String) -> List<String>,
        val wrongKind: (Localisation) -> Pair<String, String>,
    ) {
        override fun toString() = name
    }

    fun cases(): List<Case> {
        val notComponent = { l: Localisation -> l.path("manager.mgr") to "is a manager, not a component" }
        val port = { l: Localisation -> l.path("laser0.rtc:laser") to "is a port, not a component, manager or directory" }
        return listOf(
            Case("ls", { listOf("ls", it) }, { it.path("laser0.rtc") + "/" to "is a component, not a directory" }),
            Case("cat", { listOf("cat", it) }, { it.host to "is a context, not a component, port or manager" }),
            Case("find", { listOf("find", it) }, port),
            Case("act", { listOf("act", it) }, notComponent),
            Case("deact", { listOf("deact", it) }, notComponent),
            Case("reset", { listOf("reset", it) }, notComponent),
            Case("exit", { listOf("exit", it) }, notComponent),
            // A port's errors name its component.
            Case("con", { listOf("con", "$it:laser", "${it.substringBeforeLast('/')}/laser_localise0.rtc:laser") }, notComponent),
            Case("dis", { listOf("dis", "$it:laser") }, notComponent),
            Case("conf", { listOf("conf", it) }, notComponent),
            Case("mgr", { listOf("mgr", it, "list") }, { it.path("laser0.rtc") to "is a component, not a manager" }),
            Case("del", { listOf("del", it) }, { it.path("laser0.rtc") to "is a live component, not a zombie" }),
            Case("watch", { listOf("watch", it, "--for", "1s") }, port),
            Case("graph", { listOf("graph", it) }, port),
        )
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `an unknown path is not found`(case: Case) {
        val unknown = localisation.path("sonar0.rtc")
        val line = runRtcoord(*case.arguments(unknown).toTypedArray()).failure()
        assertEquals("rtcoord: $unknown: not found", line)
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `a path of the wrong kind says what it is`(case: Case) {
        val (path, reason) = case.wrongKind(localisation)
        val line = runRtcoord(*case.arguments(path).toTypedArray()).failure()
        assertEquals("rtcoord: ${path.removeSuffix("/")}: $reason", line)
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `an unreachable name server fails fast and says so`(case: Case) {
        val dead = deadNameServer()
        val started = System.nanoTime()
        val line = runRtcoord(*case.arguments("/$dead/${localisation.host.substringAfterLast('/')}/laser0.rtc").toTypedArray()).failure()
        assertTrue(line.startsWith("rtcoord: /$dead: unreachable ("), line)
        assertTrue(System.nanoTime() - started < 2_000_000_000L, "took ${(System.nanoTime() - started) / 1_000_000} ms")
    }
}
