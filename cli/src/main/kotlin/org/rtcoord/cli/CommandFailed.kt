package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktError

/**
 * A command that could not do its work: printed as the single line `rtcoord: <what>: <why>` on stderr, exit status 1.
 * Line breaks in [what] (some CORBA messages carry them) are folded into spaces.
 */
class CommandFailed(what: String) : CliktError("rtcoord: " + oneLine(what), statusCode = 1)

private fun oneLine(text: String): String = text.lines().map { it.trim() }.filter { it.isNotEmpty() }.joinToString(" ")
