package org.rtcoord.cli.serve

import org.rtcoord.RtcTree

/** What a [LiveServer] serves: a system followed live, or a recording of one replayed. */
internal sealed interface Served {
    /** The system in [tree], as [view] follows it. */
    class Live(val tree: RtcTree, val view: LiveView) : Served

    /** [recording], played back in the page; nothing can be operated. */
    class Replayed(val recording: Recording) : Served
}
