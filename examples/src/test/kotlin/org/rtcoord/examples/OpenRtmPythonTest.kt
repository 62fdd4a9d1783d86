package org.rtcoord.examples

import org.junit.jupiter.api.Test

/**
 * The paper's coordinator against real OpenRTM-aist-Python managers and components ([OpenRtmScenarios]): skipped unless
 * `RTCOORD_OPENRTM_PYTHON` names an installation.
 */
class OpenRtmPythonTest {
    @Test
    fun `data - a tap decodes a real out-port's scans, and its connector leaves with it`(): Unit =
        OpenRtmScenarios.data(OpenRtmPython.named())

    @Test
    fun `localisation - a laser that stays broken is replaced by the odometry-gyro localiser a real master creates`():
        Unit = OpenRtmScenarios.localisation(OpenRtmPython.named())

    @Test
    fun `supervision - the slave manager hosting the pipeline is killed, and a real master re-creates it in a slave it starts`():
        Unit = OpenRtmScenarios.supervision(OpenRtmPython.named())

    @Test
    fun `fidelity - the real system saved and simulated, with a second slave, service ports and constraints, shows no difference`():
        Unit =
        OpenRtmPython.named().let { installation ->
            OpenRtmSimulationScenarios.fidelity(installation, installation::startExtras)
        }

    @Test
    fun `paper's test on the copy - localisation test kts passes on the simulation of the saved real system`(): Unit =
        OpenRtmSimulationScenarios.paperTestOnCopy(OpenRtmPython.named())

    @Test
    fun `modes - with a laser that stays broken the system runs on odometry, and on the laser again once it is repaired`():
        Unit = OpenRtmScenarios.modes(OpenRtmPython.named())

    @Test
    fun `logs - a standalone component's warning, sent by OpenRTM's FluentLogger, is its LogRecord and fires a rule`():
        Unit = OpenRtmPythonLogs.logs(OpenRtmPython.named())
}
