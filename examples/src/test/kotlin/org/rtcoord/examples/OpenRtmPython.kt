package org.rtcoord.examples

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.Assumptions.assumeTrue

/**
 * OpenRTM-aist-Python: the interpreter named by `RTCOORD_OPENRTM_PYTHON`, which must import `OpenRTM_aist`, running
 * `rtcd_python`'s loop, and the modules in `examples/openrtm-python`.
 */
class OpenRtmPython private constructor(private val python: String) : OpenRtmInstallation {
    override val label: String
        get() = "real OpenRTM-aist-Python"

    override val components: Path = Paths.get("openrtm-python").toAbsolutePath()

    override fun module(type: String): String = "$type.py"

    override fun daemon(conf: Path): List<String> = listOf(python, "-c", RTCD, "-f", conf.toString())

    override fun sharedLines(directory: Path, shared: Path): List<String> {
        val rtcd = directory.resolve("rtcd")
        Files.write(rtcd, listOf("#!/bin/sh", "exec '$python' -c '$RTCD' \"$@\""))
        rtcd.toFile().setExecutable(true)
        return listOf("manager.modules.Python.manager_cmd: $rtcd")
    }

    // A slave started by hand is named `manager` like its master: OpenRTM-aist-Python's default.
    override val slaveLines: List<String>
        get() = emptyList()

    /**
     * Compiles [idl] into Python stubs in [directory] with the installation's omniidl, as an example's `gen.sh` would.
     */
    fun pythonStubs(idl: Path, directory: Path) {
        val omniidl = Paths.get(python).resolveSibling("omniidl")
        val process =
            ProcessBuilder(omniidl.toString(), "-bpython", "-C$directory", idl.toString())
                .redirectErrorStream(true)
                .start()
        val output = process.inputStream.bufferedReader().readText()
        check(process.waitFor() == 0) { "omniidl failed on $idl: $output" }
    }

    /**
     * Starts a second slave of [system]'s master, `extras`, hosting OpenRTM-aist-Python's own ConfigSample (its hidden
     * `__widget__` and `__constraints__` sets, `mode0` and `mode1`) and SimpleService's `MyServiceProvider` and
     * `MyServiceConsumer`, whose service ports (`MyService`, interface `myservice0` of type `MyService`) are connected.
     * All inactive.
     */
    fun startExtras(system: OpenRtmSystem) {
        val examples = examples()
        val stubs = Files.createDirectories(system.directory.resolve("extras"))
        pythonStubs(examples.resolve("SimpleService/MyService.idl"), stubs)
        system.startSlave(
            "extras",
            stubs,
            listOf(examples.resolve("ConfigSample"), examples.resolve("SimpleService")),
            listOf("ConfigSample0", "MyServiceProvider0", "MyServiceConsumer0"),
            "manager.modules.preload: ConfigSample.py, MyServiceProvider.py, MyServiceConsumer.py",
            "manager.components.precreate: ConfigSample, MyServiceProvider, MyServiceConsumer",
            "example.ConfigSample.config_file: ${examples.resolve("ConfigSample/configsample.conf")}",
            "exec_cxt.periodic.rate: 20",
        )
        kotlinx.coroutines.runBlocking {
            system.witness.connect(
                system.path("MyServiceProvider0.rtc:MyService"),
                system.path("MyServiceConsumer0.rtc:MyService"),
            )
        }
    }

    /** OpenRTM-aist-Python's Fluentd logger plugin in the installation, which imports `fluent-logger`. */
    fun fluentLogger(): Path = examples().resolveSibling("ext/logger/fluentlogger/FluentLogger.py")

    /** The directory of OpenRTM-aist-Python's own examples in the installation. */
    fun examples(): Path =
        Paths.get(
            ProcessBuilder(python, "-c", "import os, OpenRTM_aist; print(os.path.dirname(OpenRTM_aist.__file__))")
                .start()
                .inputStream
                .bufferedReader()
                .readText()
                .trim(),
            "examples",
        )

    companion object {
        /** What `rtcd_python` runs: a manager with the command line's options, its components and its loop. */
        private const val RTCD =
            "import sys, OpenRTM_aist; m = OpenRTM_aist.Manager.init(sys.argv); m.activateManager(); m.runManager()"

        /** The installation `RTCOORD_OPENRTM_PYTHON` names; skips the test when it names none. */
        fun named(): OpenRtmPython {
            val python = System.getenv("RTCOORD_OPENRTM_PYTHON")
            assumeTrue(
                python != null,
                "set RTCOORD_OPENRTM_PYTHON to a Python that imports OpenRTM_aist to run the localisation scenario on real OpenRTM-aist",
            )
            return OpenRtmPython(python!!)
        }
    }
}
