package org.rtcoord.cli.json

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement

/** A sample as `print --json` gives it, one a line: its time stamp (null when it has none), its type and its value. */
@Serializable
internal class SampleJson(
    /** The sample's time stamp, ISO-8601 in UTC. */
    val time: String?,
    /** Its type: OpenRTM's simple name for known types, the repository id for others. */
    val type: String,
    /**
     * A structure's members as an object, a sequence as an array, an unknown type's bytes in hex, else the value as
     * text.
     */
    val value: JsonElement,
)
