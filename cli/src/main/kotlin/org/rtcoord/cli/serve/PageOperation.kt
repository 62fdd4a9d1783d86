package org.rtcoord.cli.serve

import org.rtcoord.ComponentNode

/** What the page may do to a component when the server lets it operate: rtshell's rtact, rtdeact and rtreset. */
internal enum class PageOperation(val word: String, val perform: suspend (ComponentNode) -> Unit) {
    ACTIVATE("activate", { it.activate() }),
    DEACTIVATE("deactivate", { it.deactivate() }),
    RESET("reset", { it.reset() }),
    ;

    companion object {
        /** The operation named [word], or null. */
        fun named(word: String?): PageOperation? = entries.firstOrNull { it.word == word }
    }
}
