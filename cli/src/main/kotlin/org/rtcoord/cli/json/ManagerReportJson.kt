package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** A manager as `cat --json` gives it: master or slave, its profile, its modules and its factories' profiles. */
@Serializable
internal class ManagerReportJson
private constructor(
    val path: String,
    /** Always `manager`. */
    val kind: String,
    val master: Boolean,
    val profile: Map<String, String>,
    val loadedModules: List<String>,
    val loadableModules: List<String>,
    val factories: List<Map<String, String>>,
) {
    constructor(
        path: String,
        master: Boolean,
        profile: Map<String, String>,
        loadedModules: List<String>,
        loadableModules: List<String>,
        factories: List<Map<String, String>>,
    ) : this(path, "manager", master, profile, loadedModules, loadableModules, factories)
}
