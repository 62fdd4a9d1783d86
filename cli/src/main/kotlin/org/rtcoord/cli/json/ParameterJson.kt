package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** One configuration parameter as `conf get --json` gives it: its [set], [name] and [value]. */
@Serializable internal class ParameterJson(val set: String, val name: String, val value: String)
