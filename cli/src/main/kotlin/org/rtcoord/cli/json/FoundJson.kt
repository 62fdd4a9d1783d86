package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** A node `find --json` found: its path and its kind in lower case. */
@Serializable internal class FoundJson(val path: String, val kind: String)
