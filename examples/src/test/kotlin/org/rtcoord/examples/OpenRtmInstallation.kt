package org.rtcoord.examples

import java.nio.file.Path

/**
 * How [OpenRtmSystem] runs managers of one real OpenRTM-aist implementation: its manager daemon, the localisation
 * system's component modules, and what every manager of the system needs to know.
 */
interface OpenRtmInstallation {
    /** How test output names it: `real OpenRTM-aist-Python`. */
    val label: String

    /** The directory holding the localisation system's component modules. */
    val components: Path

    /** Where managers find modules: [components], and any the installation loads besides. */
    val loadPath: List<Path>
        get() = listOf(components)

    /** The file of [type]'s module, as a manager loads it from its load path: `laser.py`, `laser.so`. */
    fun module(type: String): String

    /** The manager daemon's command line, with its configuration file [conf]. */
    fun daemon(conf: Path): List<String>

    /**
     * The configuration lines every manager of the system gets, after the system's own: how a master starts a slave
     * (`manager.modules.<language>.manager_cmd`, a script it may write into [directory]), where modules are found.
     * [shared] is the file those lines will be in.
     */
    fun sharedLines(directory: Path, shared: Path): List<String>

    /** The lines of the slave manager started by hand, besides `manager.is_master: NO` and its modules. */
    val slaveLines: List<String>
}
