package org.rtcoord.cli

import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import org.rtcoord.ManagerNode
import org.rtcoord.RtcPath
import org.rtcoord.cli.json.ManagerReportJson

/** What `cat` shows of a manager: its profile, its modules (loaded and loadable) and its factories. */
internal class ManagerReport
private constructor(
    private val path: RtcPath,
    private val master: Boolean,
    private val profile: Map<String, String>,
    private val loaded: List<String>,
    private val loadable: List<String>,
    private val factories: List<Map<String, String>>,
) {
    /** The report as text; [long] adds every property of each factory. */
    fun lines(long: Boolean): List<String> = buildList {
        add("${path.name}  ${if (master) "master" else "slave"}")
        add("  Profile")
        addAll(aligned(sorted(profile), "    "))
        add("  Loaded modules")
        loaded.forEach { add("    $it") }
        add("  Loadable modules")
        loadable.forEach { add("    $it") }
        add("  Factories")
        if (long) {
            factories.forEach { factory ->
                add("    ${factoryName(factory)}")
                addAll(aligned(sorted(factory), "      "))
            }
        } else {
            addAll(aligned(factories.map { listOf(factoryName(it), it["description"].orEmpty()) }, "    "))
        }
    }

    /** The report for `--json`. */
    fun toJson(): ManagerReportJson =
        ManagerReportJson(
            path.toString(),
            master,
            profile.toSortedMap(),
            loaded,
            loadable,
            factories.map { it.toSortedMap() },
        )

    companion object {
        /** Reads [manager] now, its calls concurrently. */
        suspend fun read(manager: ManagerNode): ManagerReport = coroutineScope {
            val master = async { manager.isMaster() }
            val profile = async { manager.profile() }
            val loaded = async { manager.loadedModules().map(::moduleName) }
            val loadable = async { manager.loadableModules().map(::moduleName) }
            val factories = async { manager.factories() }
            ManagerReport(
                manager.path,
                master.await(),
                profile.await(),
                loaded.await(),
                loadable.await(),
                factories.await(),
            )
        }

        /**
         * A module by the name OpenRTM gives it: loaded modules carry `file_path`, loadable ones `module_file_path`.
         */
        fun moduleName(profile: Map<String, String>): String =
            profile["file_path"] ?: profile["module_file_path"] ?: profile["module_file_name"] ?: profile.toString()

        /** A factory by the component type it creates. */
        fun factoryName(profile: Map<String, String>): String =
            profile["implementation_id"] ?: profile["type_name"] ?: "?"
    }
}
