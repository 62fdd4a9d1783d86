package org.rtcoord.profile.internal

import org.rtcoord.profile.Condition
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent

/**
 * Writes the XML form with the prefixes and `xsi:type`s RTSystemEditor and rtsprofile use (`rts:`,
 * `rtsExt:`), indented, extension data and unknown content included.
 */
internal class XmlProfileWriter {
    private val out = StringBuilder()
    private var depth = 0

    fun write(profile: RtsProfile): String {
        out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n")
        element(
            "rts:RtsProfile",
            listOf(
                "xmlns:rts" to RTS_NS, "xmlns:rtsExt" to RTS_EXT_NS, "xmlns:xsi" to XSI_NS,
                "rts:id" to profile.id, "rts:abstract" to profile.abstract, "rts:creationDate" to profile.creationDate,
                "rts:updateDate" to profile.updateDate, "rts:version" to profile.version,
            ),
            profile.ext,
        ) {
            profile.components.forEach { component(it) }
            profile.groups.forEach { group ->
                element("rts:Groups", listOf("rts:groupID" to group.groupId), group.ext) {
                    group.members.forEach { target("rts:Members", it) }
                }
            }
            profile.dataPortConnectors.forEach { connector("rts:DataPortConnectors", "dataport_connector_ext", "rts:sourceDataPort", "rts:targetDataPort", it) }
            profile.servicePortConnectors.forEach { connector("rts:ServicePortConnectors", "serviceport_connector_ext", "rts:sourceServicePort", "rts:targetServicePort", it) }
            profile.orderings.toSortedMap().forEach { (kind, ordering) ->
                element("rts:${kind.xmlName}", emptyList(), ordering.ext) { ordering.targets.forEach { orderedTarget(it) } }
            }
        }
        return out.toString()
    }

    private fun component(c: ProfileComponent) {
        val attributes = listOf(
            "xsi:type" to "rtsExt:component_ext", "rts:id" to c.id, "rts:pathUri" to c.pathUri,
            "rts:activeConfigurationSet" to c.activeConfigurationSet.ifEmpty { null }, "rts:instanceName" to c.instanceName,
            "rts:compositeType" to c.compositeType, "rts:isRequired" to c.isRequired.toString(),
        )
        element("rts:Components", attributes, c.ext) {
            c.dataPorts.forEach { element("rts:DataPorts", listOf("xsi:type" to "rtsExt:dataport_ext", "rts:name" to it.name), it.ext) }
            c.servicePorts.forEach { element("rts:ServicePorts", listOf("xsi:type" to "rtsExt:serviceport_ext", "rts:name" to it.name), it.ext) }
            c.configurationSets.forEach { set ->
                element("rts:ConfigurationSets", listOf("rts:id" to set.id), set.ext) {
                    set.data.forEach { (name, data) -> element("rts:ConfigurationData", listOf("rts:name" to name, "rts:data" to data)) }
                }
            }
            c.executionContexts.forEach { ec ->
                val ecAttributes = listOf("xsi:type" to "rtsExt:execution_context_ext", "rts:id" to ec.id, "rts:kind" to ec.kind, "rts:rate" to ec.rate?.toString())
                element("rts:ExecutionContexts", ecAttributes, ec.ext) { ec.participants.forEach { participant(it) } }
            }
            c.participants.forEach { participant(it) }
        }
    }

    private fun participant(target: TargetComponent) {
        element("rts:Participants", emptyList()) { target("rts:Participant", target) }
    }

    private fun target(name: String, t: TargetComponent, extra: List<Pair<String, String?>> = emptyList()) {
        val type = when {
            t.portName != null -> "rtsExt:target_port_ext"
            t.contextId != null -> "rtsExt:target_context_ext"
            else -> "rtsExt:target_component_ext"
        }
        val attributes = listOf("xsi:type" to type, "rts:componentId" to t.componentId, "rts:instanceName" to t.instanceName, "rts:portName" to t.portName, "rts:id" to t.contextId) + extra
        element(name, attributes, t.ext)
    }

    private fun connector(name: String, type: String, sourceName: String, targetName: String, c: PortConnector) {
        val attributes = listOf(
            "xsi:type" to "rtsExt:$type", "rts:connectorId" to c.connectorId, "rts:name" to c.name, "rts:dataType" to c.dataType,
            "rts:interfaceType" to c.interfaceType, "rts:dataflowType" to c.dataflowType, "rts:subscriptionType" to c.subscriptionType,
            "rts:pushInterval" to c.pushInterval?.toString(), "rts:transMethod" to c.transMethod,
        )
        element(name, attributes, c.ext) {
            target(sourceName, c.source)
            target(targetName, c.target)
        }
    }

    private fun orderedTarget(t: OrderedTarget) {
        element("rts:targets", listOf("xsi:type" to "rtsExt:condition_ext", "rts:sequence" to t.sequence.toString()), t.ext) {
            target("rts:TargetComponent", t.target)
            when (val condition = t.condition) {
                is Condition.WaitTime -> element("rts:WaitTime", listOf("rts:waitTime" to condition.milliseconds.toString()))
                is Condition.Preceding -> {
                    val attributes = listOf("rts:timeout" to condition.timeoutMillis.toString(), "rts:sendingTiming" to condition.sendingTiming)
                    element("rts:Preceding", attributes) { condition.components.forEach { target("rts:PrecedingComponents", it) } }
                }
                Condition.None -> Unit
            }
        }
    }

    /** Writes one element: [attributes] (null values left out), then [ext], then [children] and [ext]'s elements. */
    private fun element(name: String, attributes: List<Pair<String, String?>>, ext: Extension = Extension(), children: () -> Unit = {}) {
        indent()
        out.append('<').append(name)
        val all = attributes.mapNotNull { (k, v) -> v?.let { k to it } } +
            listOfNotNull(ext.comment?.let { "rtsExt:comment" to it }, ext.visible?.let { "rtsExt:visible" to it.toString() }) +
            ext.unknownAttributes.toList()
        all.forEach { (k, v) -> out.append(' ').append(k).append("=\"").append(escape(v)).append('"') }
        val mark = out.length
        out.append(">\n")
        depth++
        children()
        ext.location?.let {
            element("rtsExt:Location", listOf("rtsExt:x" to "${it.x}", "rtsExt:y" to "${it.y}", "rtsExt:height" to "${it.height}", "rtsExt:width" to "${it.width}", "rtsExt:direction" to it.direction))
        }
        ext.properties.forEach { (k, v) -> element("rtsExt:Properties", listOf("rtsExt:name" to k, "rtsExt:value" to v.ifEmpty { null })) }
        ext.unknownElements.forEach { foreign(it) }
        depth--
        if (out.length == mark + 2) {
            out.setLength(mark)
            out.append("/>\n")
        } else {
            indent()
            out.append("</").append(name).append(">\n")
        }
    }

    private fun foreign(e: ForeignElement) {
        if (e.children.isEmpty() && e.text.isNotEmpty()) {
            indent()
            out.append('<').append(e.name)
            e.attributes.forEach { (k, v) -> out.append(' ').append(k).append("=\"").append(escape(v)).append('"') }
            out.append('>').append(escape(e.text)).append("</").append(e.name).append(">\n")
        } else {
            element(e.name, e.attributes.toList()) { e.children.forEach { foreign(it) } }
        }
    }

    private fun indent() {
        repeat(depth) { out.append("    ") }
    }

    private fun escape(text: String) = buildString {
        for (c in text) {
            when (c) {
                '&' -> append("&amp;")
                '<' -> append("&lt;")
                '>' -> append("&gt;")
                '"' -> append("&quot;")
                '\n' -> append("&#10;")
                '\r' -> append("&#13;")
                '\t' -> append("&#9;")
                else -> append(c)
            }
        }
    }
}
