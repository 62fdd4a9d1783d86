package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** The component `mgr create --json` created, by its path. */
@Serializable internal class CreatedJson(val path: String)
