package org.rtcoord.runtime

import OpenRTM.InPortCdr
import OpenRTM.InPortCdrPOA
import OpenRTM.PortStatus

/** The `InPortCdr` an in-port publishes: it decodes each pushed sample, keeps the latest and calls [received]. */
internal class InPortServant(private val type: DataType, private val received: () -> Unit) : InPortCdrPOA() {
    lateinit var ref: InPortCdr

    @Volatile var latest: Sample? = null
        private set

    override fun put(data: ByteArray): PortStatus = try {
        latest = type.decode(data)
        received()
        PortStatus.PORT_OK
    } catch (e: IllegalArgumentException) {
        PortStatus.PORT_ERROR
    }
}
