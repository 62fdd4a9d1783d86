package org.rtcoord.examples

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.Assumptions.assumeTrue

/** The three OpenRTM-aist C++ 2.0 builds the tests run on, by the prefix `scripts/openrtm-cpp.sh` builds. */
enum class OpenRtmCppBuild(val prefix: String, val preloadsObserverModule: Boolean, val description: String) {
    /**
     * The project's default build (`OBSERVER_ENABLE=OFF`) with the FSM4RTC observer module preloaded:
     * `RTC::ComponentObserver` only.
     */
    DEFAULT("default", true, "default build, FSM4RTC observer module preloaded"),

    /** The default build without the module: no ComponentObserver at all, so rtcoord polls. */
    NO_OBSERVER("default", false, "default build, no observer"),

    /** `OBSERVER_ENABLE=ON` with the module preloaded: both flavours offered. */
    BOTH_OBSERVERS("observer", true, "OBSERVER_ENABLE=ON, FSM4RTC observer module preloaded"),
}

/**
 * OpenRTM-aist C++ 2.0 as `scripts/openrtm-cpp.sh` builds it under `RTCOORD_OPENRTM_CPP`: `rtcd2` from [build]'s
 * prefix, and the modules of `examples/openrtm-cpp` built against it there.
 */
class OpenRtmCpp private constructor(root: Path, val build: OpenRtmCppBuild) : OpenRtmInstallation {
    private val prefix = root.resolve(build.prefix)

    override val label: String
        get() = "real OpenRTM-aist C++ (${build.description})"

    override val components: Path = prefix.resolve("components")

    /** Where `ComponentObserverConsumer.so`, the FSM4RTC observer module, is installed. */
    private val observerModules: Path = prefix.resolve("lib/openrtm-2.0/sdo")

    override val loadPath: List<Path>
        get() = listOf(components, observerModules)

    override fun module(type: String): String = "$type.so"

    override fun daemon(conf: Path): List<String> =
        listOf(prefix.resolve("bin/rtcd2").toString(), "-f", conf.toString())

    override fun sharedLines(directory: Path, shared: Path): List<String> {
        // A slave the master starts gets only -o options (ManagerServant::createComponentByManagerName):
        // the script gives it the system's configuration file.
        val rtcd = directory.resolve("rtcd2")
        Files.write(rtcd, listOf("#!/bin/sh", "exec '${prefix.resolve("bin/rtcd2")}' -f '$shared' \"$@\""))
        rtcd.toFile().setExecutable(true)
        return listOfNotNull(
            "manager.modules.C++.manager_cmd: $rtcd",
            // A slave reads a module's profile with rtcprof2 before loading it for a type it has no factory for.
            "manager.modules.C++.profile_cmd: ${prefix.resolve("bin/rtcprof2")}",
            "manager.preload.modules: ComponentObserverConsumer.so".takeIf { build.preloadsObserverModule },
            // rtcd2's default is 1000 Hz, in every slave the master starts.
            "exec_cxt.periodic.rate: 20",
        )
    }

    // A C++ slave finds its master by manager.name (ManagerServant::findManager): it carries the master's
    // name, and its own instance name tells it apart.
    override val slaveLines: List<String>
        get() = listOf("manager.name: manager", "manager.instance_name: pipeline")

    companion object {
        /** [build] of the installation `RTCOORD_OPENRTM_CPP` names; skips the test when it names none. */
        fun named(build: OpenRtmCppBuild): OpenRtmCpp {
            val root = System.getenv("RTCOORD_OPENRTM_CPP")
            assumeTrue(
                root != null,
                "set RTCOORD_OPENRTM_CPP to what scripts/openrtm-cpp.sh built to run the scenarios on real OpenRTM-aist C++",
            )
            val installation = OpenRtmCpp(Paths.get(root!!), build)
            check(Files.isExecutable(installation.prefix.resolve("bin/rtcd2"))) {
                "${installation.prefix}: no bin/rtcd2; run scripts/openrtm-cpp.sh"
            }
            return installation
        }
    }
}
