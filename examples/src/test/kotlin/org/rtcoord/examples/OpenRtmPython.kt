package org.rtcoord.examples

import org.junit.jupiter.api.Assumptions.assumeTrue
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/**
 * OpenRTM-aist-Python: the interpreter named by `RTCOORD_OPENRTM_PYTHON`, which must import
 * `OpenRTM_aist`, running `rtcd_python`'s loop, and the modules in `examples/openrtm-python`.
 */
class OpenRtmPython private constructor(private val python: String) : OpenRtmInstallation {
    override val label: String get() = "real OpenRTM-aist-Python"

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
    override val slaveLines: List<String> get() = emptyList()

    /** The directory of OpenRTM-aist-Python's own examples in the installation. */
    fun examples(): Path = Paths.get(
        ProcessBuilder(python, "-c", "import os, OpenRTM_aist; print(os.path.dirname(OpenRTM_aist.__file__))").start().inputStream.bufferedReader().readText().trim(),
        "examples",
    )

    companion object {
        /** What `rtcd_python` runs: a manager with the command line's options, its components and its loop. */
        private const val RTCD = "import sys, OpenRTM_aist; m = OpenRTM_aist.Manager.init(sys.argv); m.activateManager(); m.runManager()"

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
