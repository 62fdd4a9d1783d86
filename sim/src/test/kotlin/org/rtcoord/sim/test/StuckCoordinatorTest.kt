package org.rtcoord.sim.test

import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/** A coordinator that stops reacting (a handler that never returns) fails its scenario once the timeline is done. */
class StuckCoordinatorTest {
    @Test
    fun `a handler that has not returned long after it fired fails the scenario, naming the rule and what fired it`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val stuck =
            folder.write("stuck.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    delay(60.seconds)\n}")
        val test =
            folder.test(
                "stuck.test.kts",
                stuck.toString(),
                """
            at(500.milliseconds) { fail("laser0") }
            expect(within = 3.seconds) { component("laser0").state() == ERROR }
            """,
            )
        // Stuck after 2 s instead of 10: the verdict is the same, reached sooner.
        val runner = CoordinatorTestRunner().apply { stuckAfter = 2.seconds }
        val result = runBlocking { runner.runAll(runner.files(listOf(test))) }.single()
        val failure = result.failures.single()
        assertEquals(stuck.toString(), failure.at)
        assertTrue(
            Regex(
                    """the coordinator stopped reacting: the handler of rule 'laser0\.rtc enters ERROR' had not returned 2s after it fired on StateChanged at \S+laser0\.rtc"""
                )
                .matches(failure.message),
            failure.message,
        )
    }
}
