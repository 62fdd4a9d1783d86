package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.testing.test
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.ValueSource

/** What the command does to start quickly, and that none of it shows. */
class CommandStartTest {
    @Test
    fun `a command line naming a subcommand that parses gets only that subcommand`() {
        assertEquals(
            listOf("ls"),
            rtcoord(listOf("-n", "localhost", "ls", "-l", "/")).registeredSubcommands().map { it.commandName },
        )
        assertEquals(
            listOf("conf"),
            rtcoord(listOf("conf", "/a/b.rtc", "list")).registeredSubcommands().map { it.commandName },
        )
        assertEquals(
            SUBCOMMANDS.keys.toList(),
            rtcoord(listOf("--version")).registeredSubcommands().map { it.commandName },
        )
        // "ls" is the name server's address here; the command is cat, which the lone ls cannot parse.
        assertEquals(
            SUBCOMMANDS.keys.toList(),
            rtcoord(listOf("-n", "ls", "cat", "/x")).registeredSubcommands().map { it.commandName },
        )
    }

    @Test
    fun `every subcommand is made under its own name`() {
        SUBCOMMANDS.forEach { (name, make) -> assertEquals(name, make().commandName) }
    }

    @ParameterizedTest
    @ValueSource(
        strings =
            [
                "",
                "--help",
                "ls --help",
                "lst",
                "ls --long",
                "conf",
                "conf --help",
                "mgr --help",
                "--timeout fast ls /",
                "-n ls cat",
                "act",
            ]
    )
    fun `help and usage errors read the same with one subcommand as with all`(line: String) {
        val argv = line.split(' ').filter { it.isNotEmpty() }
        fun outcome(command: Rtcoord) =
            command.test(argv) { command.execute(it) }.let { Triple(it.statusCode, it.stdout, it.stderr) }
        assertEquals(outcome(rtcoord()), outcome(rtcoord(argv)))
    }

    @Test
    fun `plain text is printed as it is, text Mordant would change goes through Mordant`() {
        class Say : CliktCommand("say") {
            val text by argument()

            override fun run() = echo(text)
        }
        fun say(text: String) = Rtcoord().subcommands(Say()).test(listOf("say", text)).stdout
        assertEquals(
            "Inactive  3/0  1/0  2/0  0/0  relay0.rtc  日本 é\n",
            say("Inactive  3/0  1/0  2/0  0/0  relay0.rtc  日本 é"),
        )
        assertEquals("a       b\n", say("a\tb"))
        assertEquals("red\n", say("\u001b[31mred\u001b[0m"))
    }
}
