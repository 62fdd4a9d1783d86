package org.rtcoord.cli.serve

import kotlinx.serialization.Serializable

/** What `GET /api/component` answers when the component at [path] could not be read, and why. */
@Serializable internal class ComponentErrorJson(val path: String, val error: String)
