package org.rtcoord.sim

import org.rtcoord.profile.ProfilePort
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.ServiceInterface

/**
 * A saved service port with the interfaces its properties give ([ProfileKeys.interfaceKey]), in their saved order; one
 * that names none (rtcryo and RTSystemEditor save none) has no interfaces. A property that cannot be read as an
 * interface is left out and named in [warnings], prefixed with [where].
 */
internal fun servicePort(port: ProfilePort, where: String, warnings: MutableList<String>): PortSpec.Service {
    val interfaces =
        port.ext.properties
            .filterKeys { it.startsWith(ProfileKeys.INTERFACE_PREFIX) }
            .mapNotNull { (key, type) ->
                val polarity = key.removePrefix(ProfileKeys.INTERFACE_PREFIX).substringBefore('.')
                val instance = key.removePrefix(ProfileKeys.INTERFACE_PREFIX).substringAfter('.', "")
                when {
                    instance.isEmpty() || type.isBlank() -> null
                    polarity == "provided" ->
                        ServiceInterface(instance, type.trim(), ServiceInterface.Polarity.PROVIDED)
                    polarity == "required" ->
                        ServiceInterface(instance, type.trim(), ServiceInterface.Polarity.REQUIRED)
                    else -> null
                }
                    ?: null.also {
                        warnings +=
                            "$where: $key='$type' is not ${ProfileKeys.INTERFACE_PREFIX}provided|required.INSTANCE=TYPE: left out"
                    }
            }
    return PortSpec.Service(port.name, interfaces)
}
