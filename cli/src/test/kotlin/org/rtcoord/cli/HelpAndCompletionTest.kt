package org.rtcoord.cli

import java.nio.file.Files
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.ValueSource

/** `rtcoord help COMMAND` and `rtcoord completion SHELL`, which a shell user reaches for first. */
class HelpAndCompletionTest {
    @Test
    fun `help COMMAND shows what COMMAND --help shows`() {
        assertEquals(runRtcoord("conf", "--help").ok(), runRtcoord("help", "conf").ok())
        assertEquals(runRtcoord("mgr", "create", "--help").ok(), runRtcoord("help", "mgr", "create").ok())
        assertEquals(runRtcoord("--help").ok(), runRtcoord("help").ok())
    }

    @Test
    fun `help of a command that does not exist is a usage error`() {
        assertTrue("no such command: lst (rtcoord has demo, run, " in runRtcoord("help", "lst").usageError())
        assertTrue("no such command: make (mgr has create, delete, " in runRtcoord("help", "mgr", "make").usageError())
    }

    @ParameterizedTest
    @ValueSource(strings = ["bash", "zsh"])
    fun `the completion script is valid shell and completes every command`(shell: String) {
        val script = runRtcoord("completion", shell).ok()
        for (command in SUBCOMMANDS.keys) assertTrue(
            Regex("""\b$command\b""").containsMatchIn(script),
            "$shell script lacks $command",
        )
        assertTrue("--nameserver" in script && "--timeout" in script, "global options")
        val file = Files.createTempFile("rtcoord-completion", ".$shell")
        try {
            Files.writeString(file, script)
            val check = ProcessBuilder("bash", "-n", file.toString()).redirectErrorStream(true).start()
            val said = check.inputStream.bufferedReader().readText()
            assertTrue(check.waitFor(30, TimeUnit.SECONDS))
            assertEquals(0, check.exitValue(), said)
        } finally {
            Files.delete(file)
        }
    }

    @Test
    fun `completion for a shell it does not know is a usage error`() {
        assertTrue("invalid choice: tcsh" in runRtcoord("completion", "tcsh").usageError())
    }
}
