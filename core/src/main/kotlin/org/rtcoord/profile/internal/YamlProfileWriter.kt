package org.rtcoord.profile.internal

import org.rtcoord.profile.Condition
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent
import org.snakeyaml.engine.v2.api.Dump
import org.snakeyaml.engine.v2.api.DumpSettings
import org.snakeyaml.engine.v2.common.FlowStyle

/**
 * Writes the YAML form as rtsprofile does: `rtsProfile:` at the top, camelCase keys, `rtsExt::` keys for extension
 * data, dates as year/month/day/hour/minute/second.
 */
internal class YamlProfileWriter {
    fun write(profile: RtsProfile): String {
        val root =
            linkedMapOf<String, Any?>(
                "id" to profile.id,
                "abstract" to profile.abstract,
                "creationDate" to date(profile.creationDate),
                "updateDate" to date(profile.updateDate),
                "version" to profile.version,
            )
        root.putIfNotEmpty("components", profile.components.map { component(it) })
        root.putIfNotEmpty(
            "groups",
            profile.groups.map { g ->
                withExt(linkedMapOf("groupId" to g.groupId, "members" to g.members.map { target(it) }), g.ext)
            },
        )
        root.putIfNotEmpty(
            "dataPortConnectors",
            profile.dataPortConnectors.map { connector(it, "sourceDataPort", "targetDataPort") },
        )
        root.putIfNotEmpty(
            "servicePortConnectors",
            profile.servicePortConnectors.map { connector(it, "sourceServicePort", "targetServicePort") },
        )
        profile.orderings.toSortedMap().forEach { (kind, ordering) ->
            root[kind.yamlKey] =
                withExt(linkedMapOf("targets" to ordering.targets.map { orderedTarget(it) }), ordering.ext)
        }
        val settings =
            DumpSettings.builder().setDefaultFlowStyle(FlowStyle.BLOCK).setIndent(2).setWidth(Int.MAX_VALUE).build()
        return Dump(settings).dumpToString(mapOf("rtsProfile" to withExt(root, profile.ext)))
    }

    private fun component(c: ProfileComponent): Map<String, Any?> {
        val map =
            linkedMapOf<String, Any?>(
                "id" to c.id,
                "pathUri" to c.pathUri,
                "instanceName" to c.instanceName,
                "compositeType" to c.compositeType,
                "isRequired" to c.isRequired,
            )
        if (c.activeConfigurationSet.isNotEmpty()) map["activeConfigurationSet"] = c.activeConfigurationSet
        map.putIfNotEmpty("dataPorts", c.dataPorts.map { withExt(linkedMapOf("name" to it.name), it.ext) })
        map.putIfNotEmpty("servicePorts", c.servicePorts.map { withExt(linkedMapOf("name" to it.name), it.ext) })
        map.putIfNotEmpty(
            "configurationSets",
            c.configurationSets.map { set ->
                withExt(
                    linkedMapOf(
                        "id" to set.id,
                        "configurationData" to set.data.map { (k, v) -> linkedMapOf("name" to k, "data" to v) },
                    ),
                    set.ext,
                )
            },
        )
        map.putIfNotEmpty(
            "executionContexts",
            c.executionContexts.map { ec ->
                val m = linkedMapOf<String, Any?>("id" to ec.id, "kind" to ec.kind)
                ec.rate?.let { m["rate"] = it }
                m.putIfNotEmpty("participants", ec.participants.map { mapOf("participant" to target(it)) })
                withExt(m, ec.ext)
            },
        )
        map.putIfNotEmpty("participants", c.participants.map { mapOf("participant" to target(it)) })
        return withExt(map, c.ext)
    }

    private fun target(t: TargetComponent): Map<String, Any?> {
        val map = linkedMapOf<String, Any?>("componentId" to t.componentId, "instanceName" to t.instanceName)
        t.portName?.let { map["portName"] = it }
        t.contextId?.let { map["id"] = it }
        return withExt(map, t.ext)
    }

    private fun connector(c: PortConnector, sourceKey: String, targetKey: String): Map<String, Any?> {
        val map = linkedMapOf<String, Any?>("connectorId" to c.connectorId, "name" to c.name)
        c.dataType?.let { map["dataType"] = it }
        c.interfaceType?.let { map["interfaceType"] = it }
        c.dataflowType?.let { map["dataflowType"] = it }
        c.subscriptionType?.let { map["subscriptionType"] = it }
        c.pushInterval?.let { map["pushInterval"] = it }
        c.transMethod?.let { map["transMethod"] = it }
        map[sourceKey] = target(c.source)
        map[targetKey] = target(c.target)
        return withExt(map, c.ext)
    }

    private fun orderedTarget(t: OrderedTarget): Map<String, Any?> {
        val map = linkedMapOf<String, Any?>("sequence" to t.sequence, "targetComponent" to target(t.target))
        when (val c = t.condition) {
            is Condition.WaitTime -> map["condition"] = mapOf("waitTime" to mapOf("waitTime" to c.milliseconds))
            is Condition.Preceding ->
                map["condition"] =
                    mapOf(
                        "preceding" to
                            linkedMapOf(
                                "timeout" to c.timeoutMillis,
                                "sendingTiming" to c.sendingTiming,
                                "precedingComponents" to c.components.map { target(it) },
                            )
                    )
            Condition.None -> Unit
        }
        return withExt(map, t.ext)
    }

    private fun withExt(map: LinkedHashMap<String, Any?>, ext: Extension): LinkedHashMap<String, Any?> {
        ext.comment?.let { map["${EXT}comment"] = it }
        ext.visible?.let { map["${EXT}visible"] = it }
        ext.location?.let {
            map["${EXT}location"] =
                linkedMapOf(
                    "x" to it.x,
                    "y" to it.y,
                    "height" to it.height,
                    "width" to it.width,
                    "direction" to it.direction,
                )
        }
        map.putIfNotEmpty(
            "${EXT}properties",
            ext.properties.map { (k, v) ->
                if (v.isEmpty()) mapOf("name" to k) else linkedMapOf("name" to k, "value" to v)
            },
        )
        map.putAll(ext.unknownAttributes)
        ext.unknownElements
            .groupBy { it.name }
            .forEach { (name, elements) ->
                map[name] = if (elements.size == 1) foreign(elements.single()) else elements.map { foreign(it) }
            }
        return map
    }

    private fun foreign(e: ForeignElement): Any? {
        if (e.attributes.isEmpty() && e.children.isEmpty()) return e.text
        val map = linkedMapOf<String, Any?>()
        map.putAll(e.attributes)
        e.children
            .groupBy { it.name }
            .forEach { (name, elements) ->
                map[name] = if (elements.size == 1) foreign(elements.single()) else elements.map { foreign(it) }
            }
        return map
    }

    private fun date(text: String): Any? {
        val match = DATE.matchEntire(text) ?: return text
        val (year, month, day, hour, minute, second) = match.destructured
        return linkedMapOf(
            "year" to year.toInt(),
            "month" to month.toInt(),
            "day" to day.toInt(),
            "hour" to hour.toInt(),
            "minute" to minute.toInt(),
            "second" to second.toInt(),
        )
    }

    private fun LinkedHashMap<String, Any?>.putIfNotEmpty(key: String, value: List<Any?>) {
        if (value.isNotEmpty()) put(key, value)
    }

    private companion object {
        const val EXT = "rtsExt::"
        val DATE = Regex("""(\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2}).*""")
    }
}
