package org.rtcoord.cli

import com.github.ajalt.clikt.completion.CompletionGenerator
import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.types.choice

/** `rtcoord completion SHELL`: the shell's completion script for every command and option. */
class CompletionCommand : CliktCommand("completion") {
    override fun help(context: Context): String =
        "Print a completion script for SHELL. The distribution archive installs them in share/bash-completion " +
            "and share/zsh; from a checkout, load one into the running shell as the examples show."

    override fun helpEpilog(context: Context): String =
        examples(
            "source <(rtcoord completion bash)" to "complete rtcoord's commands and options in this bash",
            "rtcoord completion zsh > ~/.zfunc/_rtcoord" to "for zsh, in a folder on fpath",
        )

    private val shell by argument("SHELL", help = "bash, zsh or fish.").choice(*SHELLS)

    override fun run() = echo(completionScript(shell), trailingNewline = false)

    internal companion object {
        val SHELLS = arrayOf("bash", "zsh", "fish")

        /** The completion script of the whole `rtcoord` command for [shell]. */
        fun completionScript(shell: String): String {
            // The generator reads the command's context, which exists only once a command line was parsed.
            val command = rtcoord().apply { resetContext() }
            return CompletionGenerator.generateCompletionForCommand(command, shell)
        }
    }
}
