package org.rtcoord.cli

/**
 * A line of stderr rewritten in place on a terminal, for progress. [write] prints without a newline; [clear] erases the
 * line if anything was shown, so the output that follows starts clean.
 */
internal class StatusLine(private val write: (String) -> Unit) {
    private var shown = false

    /** Replaces the line with [text]. */
    fun show(text: String) {
        write("\r$text$ERASE_TO_END")
        shown = true
    }

    /** Erases the line. */
    fun clear() {
        if (shown) write("\r$ERASE_TO_END")
        shown = false
    }

    private companion object {
        const val ERASE_TO_END = "\u001b[K"
    }
}
