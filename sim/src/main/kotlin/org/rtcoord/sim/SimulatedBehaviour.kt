package org.rtcoord.sim

import org.rtcoord.datatypes.MadeUpValues
import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentContext
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.Sample

/**
 * What a simulated component does: one without in-ports is a source, writing every out-port on every execution; one
 * with in-ports writes its out-ports whenever an input brought a sample it has not used, so data flows through the
 * simulated network as through the real one. Each sample is made up from the time it is written and the port's full
 * name ([MadeUpValues]): a test can tell what a port sent when. An out-port whose type has no known IDL writes nothing.
 */
internal class SimulatedBehaviour(ports: List<PortSpec>) : Behaviour {
    private val inputs = ports.filterIsInstance<PortSpec.DataIn>().map { it.name }
    private val outputs = ports.filterIsInstance<PortSpec.DataOut>().filter { it.dataType.isEncodable }
    private var values: List<MadeUpValues>? = null
    private var lastUsed = emptyList<Sample?>()

    override fun onExecute(rtc: ComponentContext): Boolean {
        if (inputs.isNotEmpty()) {
            val latest = inputs.map(rtc::latest)
            if (latest == lastUsed || latest.all { it == null }) return true
            lastUsed = latest
        }
        val made =
            values
                ?: outputs
                    .map { MadeUpValues(it.dataType.idl!!, seed = "${rtc.instanceName}.${it.name}".hashCode()) }
                    .also { values = it }
        val now = System.currentTimeMillis() * 1_000_000
        outputs.forEachIndexed { index, port -> rtc.write(port.name, made[index].at(now)!!) }
        return true
    }
}
