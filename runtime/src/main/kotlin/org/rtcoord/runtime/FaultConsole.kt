package org.rtcoord.runtime

import RTC.ReturnCode_t
import java.io.PrintStream

/**
 * The commands a runtime process takes on stdin, one a line, to inject faults by hand (`scripts/fixtures`, `rtcoord
 * sim`) into the [components] there are at that moment: each is acknowledged with one line on [out] saying what it did,
 * each mistake with one line on [err], prefixed with [tool].
 */
public class FaultConsole(
    private val components: () -> List<RuntimeComponent>,
    private val out: PrintStream,
    private val err: PrintStream,
    private val tool: String = "fixtures",
) {
    /** Acts on one line of input. */
    public fun execute(line: String) {
        val words = line.trim().split(Regex("\\s+")).filter { it.isNotEmpty() }
        if (words.isEmpty()) return
        val command = words[0]
        if (command == "help") return say(HELP)
        if (command !in COMMANDS) return complain("unknown command '$command' ('help' lists them)")
        if (words.size != 2) return complain("$command needs one component name: $command NAME")
        val name = words[1]
        val component =
            components().firstOrNull { it.instanceName == name && !it.isExited }
                ?: return complain(
                    "no component '$name' (components: ${components().filterNot { it.isExited }.joinToString { it.instanceName }.ifEmpty { "none" }})"
                )
        when (command) {
            "activate" ->
                component.activate().let { code ->
                    if (code == ReturnCode_t.RTC_OK) say("activated $name")
                    else complain("activate $name: ${code.value().let(::returnCode)}")
                }
            "fail" -> {
                component.fail()
                say("failed $name: its next execution fails into ERROR; a reset recovers it")
            }
            "break" -> {
                component.breakDown()
                say("broke $name: it goes to ERROR and every reset fails until 'repair $name'")
            }
            "hang" -> {
                component.hangExecution()
                val now =
                    if (awaitStuck(component)) "its execution context is stalled in it"
                    else "it is not executing now; its context stalls once it does"
                say(
                    "hung $name: its on_execute never returns ($now): it keeps its state, and activate, deactivate and reset " +
                        "answer RTC_ERROR after 0.5 s, until 'repair $name'"
                )
            }
            "freeze" -> {
                component.freezeOutput()
                say(
                    "froze $name: it stays ${component.state.label()} and executes, but its out-ports publish nothing until 'repair $name'"
                )
            }
            "repair" -> {
                component.repair()
                component.resumeExecution()
                component.thawOutput()
                say("repaired $name: resets succeed, it executes and publishes again")
            }
            "lose-connectors" -> {
                component.loseConnectors()
                say(
                    "lost the connectors of $name, as an out-port whose peer stopped answering drops them: it runs on, unconnected"
                )
            }
            "exit" -> {
                component.exit()
                say("exited $name, as rtexit does: it finalised, and its name leaves naming")
            }
        }
    }

    /**
     * Whether [component]'s context reaches its hung execution within two periods and a second: at once if it is ACTIVE
     * (the next tick runs it), never if it is not executing.
     */
    private fun awaitStuck(component: RuntimeComponent): Boolean {
        if (component.state != RTC.LifeCycleState.ACTIVE_STATE) return false
        val deadline = System.nanoTime() + (2_000_000_000 / component.type.rate).toLong() + 1_000_000_000L
        while (!component.isContextStuck && System.nanoTime() < deadline) Thread.sleep(10)
        return component.isContextStuck
    }

    private fun say(text: String) {
        out.println(text)
        out.flush()
    }

    private fun complain(text: String) {
        err.println("$tool: $text")
        err.flush()
    }

    public companion object {
        private val COMMANDS = setOf("activate", "fail", "break", "hang", "freeze", "repair", "lose-connectors", "exit")

        private val RETURN_CODES =
            listOf("RTC_OK", "RTC_ERROR", "BAD_PARAMETER", "UNSUPPORTED", "OUT_OF_RESOURCES", "PRECONDITION_NOT_MET")

        private fun RTC.LifeCycleState.label(): String =
            when (value()) {
                RTC.LifeCycleState._ACTIVE_STATE -> "ACTIVE"
                RTC.LifeCycleState._INACTIVE_STATE -> "INACTIVE"
                RTC.LifeCycleState._ERROR_STATE -> "ERROR"
                else -> "CREATED"
            }

        private fun returnCode(value: Int): String = RETURN_CODES.getOrElse(value) { "return code $value" }

        /** What `help` prints, and the process's usage ends with. */
        public val HELP: String =
            """
            Commands on stdin, one a line; each is answered with a line saying what it did:
              activate NAME   activate the component, as rtact does
              fail NAME       its next execution fails: it goes to ERROR; a reset recovers it
              break NAME      it goes to ERROR and every reset fails (on_reset fails) until repair
              hang NAME       its on_execute never returns: its execution context stalls, it keeps its state, no data
                              flows, and activate/deactivate/reset answer RTC_ERROR after 0.5 s until repair
              freeze NAME     its out-ports stop publishing while it stays ACTIVE and executes (a sensor gone silent)
              repair NAME     end break, hang and freeze: resets succeed, it executes and publishes again
              lose-connectors NAME
                              every connector of its ports is lost, as when its peer stops answering: both ends drop it
              exit NAME       the component exits, as rtexit does
              help            this list
            """
                .trimIndent()
    }
}
