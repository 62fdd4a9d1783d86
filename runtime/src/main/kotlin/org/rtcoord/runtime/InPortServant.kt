package org.rtcoord.runtime

import OpenRTM.InPortCdr
import OpenRTM.InPortCdrPOA
import OpenRTM.PortStatus

/**
 * The `InPortCdr` of one connector of an in-port, as OpenRTM's `InPortCorbaCdrProvider` is: it decodes each pushed
 * sample in the byte order the connector negotiated and hands it to [received]. A type whose IDL is not known is taken
 * as it comes: its raw bytes, stamped 0.
 */
internal class InPortServant(
    private val type: DataType,
    private val littleEndian: Boolean,
    private val received: (Sample) -> Unit,
) : InPortCdrPOA() {
    lateinit var ref: InPortCdr

    override fun put(data: ByteArray): PortStatus =
        try {
            received(if (type.isEncodable) type.decode(data, littleEndian) else Sample(0, data.copyOf()))
            PortStatus.PORT_OK
        } catch (e: IllegalArgumentException) {
            PortStatus.PORT_ERROR
        }
}
