package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/**
 * Configuration sets as `conf list --json` and `cat -l --json` give them: the [active] set's id (null when none is) and
 * each set's parameters.
 */
@Serializable internal class ConfigurationJson(val active: String?, val sets: Map<String, Map<String, String>>)
