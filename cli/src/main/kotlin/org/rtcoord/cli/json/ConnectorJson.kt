package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** The connector `con --json` made: its [id], [name] and [properties] by key. */
@Serializable internal class ConnectorJson(val id: String, val name: String, val properties: Map<String, String>)
