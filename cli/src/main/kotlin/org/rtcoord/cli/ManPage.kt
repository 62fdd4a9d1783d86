package org.rtcoord.cli

import com.github.ajalt.clikt.core.BaseCliktCommand
import com.github.ajalt.clikt.core.PrintHelpMessage

/**
 * rtcoord(1), made from the commands' own help so that it never says something `--help` does not: the root command's
 * help as the description, then each command's help in full.
 */
internal object ManPage {
    fun render(version: String): String = buildString {
        appendLine(""".TH RTCOORD 1 "" "rtcoord $version" "User Commands"""")
        appendLine(".SH NAME")
        appendLine("""rtcoord \- browse, operate and coordinate OpenRTM-aist RT systems""")
        appendLine(".SH SYNOPSIS")
        appendLine(""".B rtcoord""")
        appendLine("""[\fIOPTIONS\fR] \fICOMMAND\fR [\fIARGUMENTS\fR]...""")
        appendLine(".SH DESCRIPTION")
        preformatted(helpText(emptyList()))
        appendLine(".SH COMMANDS")
        for (command in commandLines(rtcoord(), emptyList())) {
            appendLine(""".SS "rtcoord ${command.joinToString(" ")}"""")
            preformatted(helpText(command))
        }
        appendLine(".SH ENVIRONMENT")
        ENVIRONMENT.forEach { (variable, meaning) -> appendLine(".TP\n.B $variable\n${escaped(meaning)}") }
        appendLine(".SH EXIT STATUS")
        appendLine(
            "0 when the command did what it was asked, 1 when it failed (one line on standard error says what and why), 2 for a usage error."
        )
        appendLine(".SH SEE ALSO")
        appendLine(
            "rtshell's rtls(1), rtcat(1), rtcon(1), rtconf(1) and rtmgr(1), whose paths and habits rtcoord keeps."
        )
    }

    /** Every command below [command] (reached by [path]), each as the words that name it, depth first. */
    private fun commandLines(command: BaseCliktCommand<*>, path: List<String>): List<List<String>> =
        command.registeredSubcommands().flatMap { sub ->
            val named = path + sub.commandName
            listOf(named) + commandLines(sub, named)
        }

    private fun helpText(command: List<String>): String {
        val message: PrintHelpMessage = helpOf(command)
        return message.context?.command?.getFormattedHelp(message).orEmpty()
    }

    /** [text] as lines troff prints as they are. */
    private fun StringBuilder.preformatted(text: String) {
        appendLine(".nf")
        text.trimEnd().lines().forEach { appendLine(escaped(it)) }
        appendLine(".fi")
    }

    /** [line] with troff's escape character doubled and a leading control character neutralised. */
    private fun escaped(line: String): String {
        val text = line.replace("\\", "\\e")
        return if (text.startsWith(".") || text.startsWith("'")) "\\&$text" else text
    }

    private val ENVIRONMENT =
        listOf(
            "RTCOORD_NAMESERVERS" to "Name servers to use when no -n is given, separated by ';'.",
            "RTCTREE_NAMESERVERS" to "rtshell's variable, used when RTCOORD_NAMESERVERS is not set.",
            "RTCOORD_CWD" to "Where relative paths start (rtshell's RTCSH_CWD is read too).",
            "RTCOORD_CACHE" to
                "Where the launcher keeps class-data archives and compiled scripts are cached (default ~/.cache/rtcoord).",
        )
}
