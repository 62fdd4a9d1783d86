package org.rtcoord.sim

import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfilePort

/** The differences of one component found in both. */
internal class ComponentDifferences(
    private val path: String,
    private val live: ProfileComponent,
    private val simulated: ProfileComponent,
) {
    private val found = mutableListOf<String>()

    fun all(): List<String> {
        compare("type", live.id, simulated.id)
        ports()
        contexts()
        configuration()
        return found
    }

    private fun compare(what: String, a: String?, b: String?) {
        if (a != b) found += "$path: $what: ${a.shown()} live, ${b.shown()} simulated"
    }

    /**
     * Each element of [live] and [simulated] by key, in key order: one only one side has is a difference (`present`
     * against `none`); those both have are compared by [both], with their subject.
     */
    private fun <T> matched(
        kind: String,
        live: Map<String, T>,
        simulated: Map<String, T>,
        both: (String, T, T) -> Unit,
    ) {
        for (key in (live.keys + simulated.keys).sorted()) {
            val subject = "$kind $key"
            val a = live[key]
            val b = simulated[key]
            if (a == null || b == null) compare(subject, a?.let { "present" }, b?.let { "present" })
            else both(subject, a, b)
        }
    }

    private fun ports() =
        matched(
            "port",
            (live.dataPorts + live.servicePorts).associateBy { it.name },
            (simulated.dataPorts + simulated.servicePorts).associateBy { it.name },
        ) { port, a, b ->
            for (key in listOf("port.port_type", "dataport.data_type")) compare(
                "$port: $key",
                a.ext.properties[key],
                b.ext.properties[key],
            )
            compare("$port: interfaces", a.interfaces(), b.interfaces())
        }

    private fun ProfilePort.interfaces(): String? =
        ext.properties
            .filterKeys { it.startsWith(ProfileKeys.INTERFACE_PREFIX) }
            .entries
            .joinToString { (key, type) ->
                "${key.removePrefix(ProfileKeys.INTERFACE_PREFIX).replace('.', ' ')} ($type)"
            }
            .ifEmpty { null }

    private fun contexts() =
        matched(
            "execution context",
            live.executionContexts.associateBy { it.id },
            simulated.executionContexts.associateBy { it.id },
        ) { context, a, b ->
            compare("$context: kind", a.kind, b.kind)
            compare("$context: rate", a.rate?.toString(), b.rate?.toString())
            compare(
                "$context: implementation",
                a.ext.properties[ProfileKeys.CONTEXT_TYPE],
                b.ext.properties[ProfileKeys.CONTEXT_TYPE],
            )
        }

    private fun configuration() {
        compare(
            "active configuration set",
            live.activeConfigurationSet.ifEmpty { null },
            simulated.activeConfigurationSet.ifEmpty { null },
        )
        matched(
            "configuration set",
            live.configurationSets.associate { "'${it.id}'" to it.data },
            simulated.configurationSets.associate { "'${it.id}'" to it.data },
        ) { set, a, b ->
            for (name in (a.keys + b.keys).sorted()) compare(
                "$set: $name",
                a[name]?.let { "'$it'" },
                b[name]?.let { "'$it'" },
            )
        }
    }
}
