package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.output.MordantHelpFormatter
import com.github.ajalt.mordant.rendering.Whitespace
import com.github.ajalt.mordant.rendering.Widget
import com.github.ajalt.mordant.widgets.Text

/**
 * Clikt's help layout, except that the epilog is printed as written: it holds the examples, whose lines and indentation
 * the default layout would reflow into one paragraph.
 */
internal class HelpFormatter(context: Context) : MordantHelpFormatter(context, showDefaultValues = true) {
    override fun renderEpilog(epilog: String): Widget = Text(epilog, whitespace = Whitespace.PRE)
}

/** An "Examples:" epilog: each command line, with what it does on the line below. */
internal fun examples(vararg commandLines: Pair<String, String>): String =
    "Examples:" + commandLines.joinToString("") { (line, what) -> "\n  $line\n      $what" }
