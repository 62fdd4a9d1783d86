package org.rtcoord.sim

import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentContext
import org.rtcoord.runtime.DataType
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.Sample

/**
 * What a simulated component does: one without in-ports is a source, writing every out-port on every
 * execution; one with in-ports writes its out-ports whenever an input brought a sample it has not used,
 * so data flows through the simulated network as through the real one.
 */
internal class SimulatedBehaviour(ports: List<PortSpec>) : Behaviour {
    private val inputs = ports.filterIsInstance<PortSpec.DataIn>().map { it.name }
    private val outputs = ports.filterIsInstance<PortSpec.DataOut>()
    private var lastUsed = emptyList<Sample?>()

    override fun onExecute(rtc: ComponentContext): Boolean {
        if (inputs.isNotEmpty()) {
            val latest = inputs.map(rtc::latest)
            if (latest == lastUsed || latest.all { it == null }) return true
            lastUsed = latest
        }
        outputs.forEach { rtc.write(it.name, value(it.dataType, rtc.tick)) }
        return true
    }

    private fun value(type: DataType, tick: Long): Any = when (type) {
        DataType.TIMED_LONG -> tick.toInt()
        DataType.TIMED_DOUBLE -> tick * 0.01
        DataType.TIMED_DOUBLE_SEQ -> doubleArrayOf(tick * 0.01, 0.0, 0.0)
        DataType.TIMED_STRING -> "tick $tick"
    }
}
