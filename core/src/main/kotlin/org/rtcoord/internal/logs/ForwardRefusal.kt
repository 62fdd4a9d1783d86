package org.rtcoord.internal.logs

/** Why a sender's input was refused; [id] is stable and lower-case, for counting and for logs. */
internal enum class ForwardRefusal(val id: String) {
    /** Not the forward protocol: MessagePack that does not decode, or a value where the protocol has none. */
    MALFORMED("malformed"),

    /** An entry or a frame over [ForwardSettings.maxRecordBytes]. */
    TOO_LARGE("too-large"),

    /** The shared-key handshake failed: a wrong key, or events before it. */
    WRONG_KEY("wrong-key"),

    /** More entries in a second than [ForwardSettings.maxEntriesPerSecond] on one connection. */
    FLOOD("flood"),

    /** A frame begun and not completed within [ForwardSettings.frameTimeout], or cut by the sender's closing. */
    INCOMPLETE_FRAME("incomplete-frame"),
}
