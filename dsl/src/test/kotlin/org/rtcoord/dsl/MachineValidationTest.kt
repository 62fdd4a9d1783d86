package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/** A machine that cannot run is rejected when its declaration ends, naming the machine, the mode and the reason. */
class MachineValidationTest {
    private val coordination = Coordination(emptyList(), TreeConfig())

    private fun problems(declare: ModeBuilder.() -> Unit): List<String> =
        assertThrows(InvalidMachineException::class.java) { coordination.modes("m", declare) }.problems

    @Test
    fun `a valid machine is kept as an inspectable model`() {
        val machine =
            coordination.modes("m") {
                initial("a")
                mode("a") {
                    network {
                        active("laser0")
                        connected("laser0:laser", "laser_localise0.rtc:laser")
                        configSet("laser_localise0", "precise")
                    }
                    on(component("laser0.rtc")).state(ERROR).where { true } goTo "b"
                }
                mode("b") {
                    entry {}
                    initial("b1")
                    mode("b1") { after(5.seconds) goTo "a" }
                }
            }
        assertEquals(listOf("m/a", "m/b", "m/b/b1"), machine.modes.map { it.path })
        assertEquals(mapOf("laser0.rtc" to true), machine.modes[0].network?.components, "plain names get .rtc")
        assertEquals(
            listOf(
                "modes m, initially a",
                "  mode a",
                "    network: active laser0.rtc",
                "    network: connected laser0.rtc:laser -> laser_localise0.rtc:laser",
                "    network: configuration sets laser_localise0.rtc=precise",
                "    on laser0.rtc enters ERROR (guarded) -> b",
                "  mode b, initially b1, entry",
                "    mode b1",
                "      after 5s -> a",
            ),
            coordination.description,
        )
    }

    @Test
    fun `a transition to an unknown mode`() {
        assertEquals(
            listOf(
                "mode 'm/a': transition on laser0.rtc enters ERROR goes to unknown mode 'degaded' (modes: a, degraded)"
            ),
            problems {
                initial("a")
                mode("a") { on(component("laser0.rtc")).state(ERROR) goTo "degaded" }
                mode("degraded")
            },
        )
    }

    @Test
    fun `an unreachable mode, reported at its outermost unreachable level`() {
        val failure =
            assertThrows(InvalidMachineException::class.java) {
                coordination.modes("m") {
                    initial("a")
                    mode("a") { on(done) goTo "b" }
                    mode("b")
                    mode("island") {
                        initial("shore")
                        mode("shore") { after(1.seconds) goTo "a" }
                    }
                }
            }
        assertEquals(
            "machine 'm': mode 'm/island' is unreachable: no transition leads to it or into it",
            failure.message,
        )
    }

    @Test
    fun `a mode entered directly is reached with its ancestors, not its parent's initial mode`() {
        assertEquals(
            listOf("mode 'm/outer/first' is unreachable: no transition leads to it or into it"),
            problems {
                initial("a")
                mode("a") { on(failed) goTo "deep" }
                mode("outer") {
                    initial("first")
                    mode("first")
                    mode("deep")
                }
            },
        )
    }

    @Test
    fun `missing, misplaced and wrong initial modes`() {
        assertEquals(
            listOf("the machine has sub-modes (a, b) but no initial(...)"),
            problems {
                mode("a")
                mode("b")
            },
        )
        assertEquals(
            listOf(
                "mode 'm/a': initial mode 'q' is not one of its sub-modes (x)",
                "mode 'm/a/x' declares initial 'y' but has no sub-modes",
            ),
            problems {
                initial("a")
                mode("a") {
                    initial("q")
                    mode("x") { initial("y") }
                }
            },
        )
        assertEquals(listOf("it declares no modes"), problems {})
    }

    @Test
    fun `names used twice, in the same machine or for two machines`() {
        assertEquals(
            listOf("the name 'a' is used 2 times (m/a, m/b/a)"),
            problems {
                initial("a")
                mode("a")
                mode("b") {
                    initial("a")
                    mode("a")
                }
            },
        )
        coordination.modes("m") {
            initial("a")
            mode("a")
        }
        assertEquals(
            listOf("another machine is named 'm'"),
            problems {
                initial("a")
                mode("a")
            },
        )
    }

    @Test
    fun `triggers without goTo, bad delays, exits of the machine itself and contradictory networks`() {
        assertEquals(
            listOf(
                "mode 'm/a': network: laser0.rtc is declared both active and inactive",
                "mode 'm/a': network: laser0.rtc:laser -> x.rtc:in is declared both connected and not connected",
                "mode 'm/a': network: 'laser*' is a pattern; a network names single components",
                "the machine itself is never left: exit actions on 'm' would never run",
                "mode 'm/a': transition on gyro0.rtc is lost has no goTo",
                "mode 'm/a': transition after 0s: the delay must be positive",
            ),
            problems {
                exit {}
                initial("a")
                mode("a") {
                    network {
                        active("laser0")
                        inactive("laser0.rtc")
                        connected("laser0:laser", "x:in")
                        disconnected("laser0.rtc:laser", "x.rtc:in")
                        active("laser*")
                    }
                    on(component("gyro0.rtc")).lost()
                    after(Duration.ZERO) goTo "a"
                }
            },
        )
    }

    @Test
    fun `in a script, the error is one line at the machine's declaration`(@TempDir directory: Path): Unit =
        runBlocking {
            val script = directory.resolve("modes.coord.kts")
            Files.writeString(
                script,
                """
                val laser = component("laser0.rtc")

                modes("system") {
                    initial("nominal")
                    mode("nominal") { on(laser).state(ERROR) goTo "degaded" }
                    mode("degraded") { after(5.seconds) goTo "nominal" }
                }
                """
                    .trimIndent(),
            )
            val failure =
                assertThrows(ScriptFailure::class.java) {
                    runBlocking { ScriptHost(directory.resolve("cache")).load(script) }
                }
            assertEquals(
                listOf(
                    "$script:3:1: machine 'system': mode 'system/nominal': transition on laser0.rtc enters ERROR " +
                        "goes to unknown mode 'degaded' (modes: nominal, degraded)"
                ),
                failure.problems,
            )
        }
}
