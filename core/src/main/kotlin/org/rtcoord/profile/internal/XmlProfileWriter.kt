package org.rtcoord.profile.internal

import java.io.StringWriter
import javax.xml.transform.OutputKeys
import javax.xml.transform.TransformerFactory
import javax.xml.transform.sax.SAXTransformerFactory
import javax.xml.transform.sax.TransformerHandler
import javax.xml.transform.stream.StreamResult
import org.rtcoord.profile.Condition
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent
import org.xml.sax.helpers.AttributesImpl

/**
 * Writes the XML form with the prefixes and `xsi:type`s RTSystemEditor and rtsprofile use (`rts:`, `rtsExt:`),
 * indented, extension data and unknown content included.
 *
 * The JDK's serializer (SAX events into an identity [javax.xml.transform.Transformer]) writes it, not its StAX writer:
 * StAX leaves line breaks and tabs in attribute values as they are, and every reader turns them into spaces, so a
 * comment or configuration value of two lines would come back as one. The serializer writes them as character
 * references.
 */
internal class XmlProfileWriter {
    private val out = StringWriter()
    private val xml: TransformerHandler =
        (TransformerFactory.newDefaultInstance() as SAXTransformerFactory).newTransformerHandler().apply {
            transformer.setOutputProperty(OutputKeys.ENCODING, "UTF-8")
            transformer.setOutputProperty(OutputKeys.INDENT, "yes")
            transformer.setOutputProperty("{http://xml.apache.org/xslt}indent-amount", "4")
            // Without a standalone declaration the JDK's serializer puts the root on the declaration's line.
            transformer.setOutputProperty(OutputKeys.STANDALONE, "yes")
            setResult(StreamResult(out))
        }

    fun write(profile: RtsProfile): String {
        xml.startDocument()
        NAMESPACES.forEach { (prefix, uri) -> xml.startPrefixMapping(prefix, uri) }
        element(
            "rts:RtsProfile",
            listOf(
                "rts:id" to profile.id,
                "rts:abstract" to profile.abstract,
                "rts:creationDate" to profile.creationDate,
                "rts:updateDate" to profile.updateDate,
                "rts:version" to profile.version,
            ),
            profile.ext,
        ) {
            profile.components.forEach { component(it) }
            profile.groups.forEach { group ->
                element("rts:Groups", listOf("rts:groupID" to group.groupId), group.ext) {
                    group.members.forEach { target("rts:Members", it) }
                }
            }
            profile.dataPortConnectors.forEach {
                connector(
                    "rts:DataPortConnectors",
                    "dataport_connector_ext",
                    "rts:sourceDataPort",
                    "rts:targetDataPort",
                    it,
                )
            }
            profile.servicePortConnectors.forEach {
                connector(
                    "rts:ServicePortConnectors",
                    "serviceport_connector_ext",
                    "rts:sourceServicePort",
                    "rts:targetServicePort",
                    it,
                )
            }
            profile.orderings.toSortedMap().forEach { (kind, ordering) ->
                element("rts:${kind.xmlName}", emptyList(), ordering.ext) {
                    ordering.targets.forEach { orderedTarget(it) }
                }
            }
        }
        NAMESPACES.keys.forEach { xml.endPrefixMapping(it) }
        xml.endDocument()
        return out.toString()
    }

    private fun component(c: ProfileComponent) {
        val attributes =
            listOf(
                "xsi:type" to "rtsExt:component_ext",
                "rts:id" to c.id,
                "rts:pathUri" to c.pathUri,
                "rts:activeConfigurationSet" to c.activeConfigurationSet.ifEmpty { null },
                "rts:instanceName" to c.instanceName,
                "rts:compositeType" to c.compositeType,
                "rts:isRequired" to c.isRequired.toString(),
            )
        element("rts:Components", attributes, c.ext) {
            c.dataPorts.forEach {
                element("rts:DataPorts", listOf("xsi:type" to "rtsExt:dataport_ext", "rts:name" to it.name), it.ext)
            }
            c.servicePorts.forEach {
                element(
                    "rts:ServicePorts",
                    listOf("xsi:type" to "rtsExt:serviceport_ext", "rts:name" to it.name),
                    it.ext,
                )
            }
            c.configurationSets.forEach { set ->
                element("rts:ConfigurationSets", listOf("rts:id" to set.id), set.ext) {
                    set.data.forEach { (name, data) ->
                        element("rts:ConfigurationData", listOf("rts:name" to name, "rts:data" to data))
                    }
                }
            }
            c.executionContexts.forEach { ec ->
                val ecAttributes =
                    listOf(
                        "xsi:type" to "rtsExt:execution_context_ext",
                        "rts:id" to ec.id,
                        "rts:kind" to ec.kind,
                        "rts:rate" to ec.rate?.toString(),
                    )
                element("rts:ExecutionContexts", ecAttributes, ec.ext) { ec.participants.forEach { participant(it) } }
            }
            c.participants.forEach { participant(it) }
        }
    }

    private fun participant(target: TargetComponent) {
        element("rts:Participants", emptyList()) { target("rts:Participant", target) }
    }

    private fun target(name: String, t: TargetComponent, extra: List<Pair<String, String?>> = emptyList()) {
        val type =
            when {
                t.portName != null -> "rtsExt:target_port_ext"
                t.contextId != null -> "rtsExt:target_context_ext"
                else -> "rtsExt:target_component_ext"
            }
        val attributes =
            listOf(
                "xsi:type" to type,
                "rts:componentId" to t.componentId,
                "rts:instanceName" to t.instanceName,
                "rts:portName" to t.portName,
                "rts:id" to t.contextId,
            ) + extra
        element(name, attributes, t.ext)
    }

    private fun connector(name: String, type: String, sourceName: String, targetName: String, c: PortConnector) {
        val attributes =
            listOf(
                "xsi:type" to "rtsExt:$type",
                "rts:connectorId" to c.connectorId,
                "rts:name" to c.name,
                "rts:dataType" to c.dataType,
                "rts:interfaceType" to c.interfaceType,
                "rts:dataflowType" to c.dataflowType,
                "rts:subscriptionType" to c.subscriptionType,
                "rts:pushInterval" to c.pushInterval?.toString(),
                "rts:transMethod" to c.transMethod,
            )
        element(name, attributes, c.ext) {
            target(sourceName, c.source)
            target(targetName, c.target)
        }
    }

    private fun orderedTarget(t: OrderedTarget) {
        element(
            "rts:targets",
            listOf("xsi:type" to "rtsExt:condition_ext", "rts:sequence" to t.sequence.toString()),
            t.ext,
        ) {
            target("rts:TargetComponent", t.target)
            when (val condition = t.condition) {
                is Condition.WaitTime ->
                    element("rts:WaitTime", listOf("rts:waitTime" to condition.milliseconds.toString()))
                is Condition.Preceding -> {
                    val attributes =
                        listOf(
                            "rts:timeout" to condition.timeoutMillis.toString(),
                            "rts:sendingTiming" to condition.sendingTiming,
                        )
                    element("rts:Preceding", attributes) {
                        condition.components.forEach { target("rts:PrecedingComponents", it) }
                    }
                }
                Condition.None -> Unit
            }
        }
    }

    /** Writes one element: [attributes] (null values left out), then [ext], then [children] and [ext]'s elements. */
    private fun element(
        name: String,
        attributes: List<Pair<String, String?>>,
        ext: Extension = Extension(),
        children: () -> Unit = {},
    ) {
        val all =
            attributes.mapNotNull { (k, v) -> v?.let { k to it } } +
                listOfNotNull(
                    ext.comment?.let { "rtsExt:comment" to it },
                    ext.visible?.let { "rtsExt:visible" to it.toString() },
                ) +
                ext.unknownAttributes.toList()
        start(name, all)
        children()
        ext.location?.let {
            element(
                "rtsExt:Location",
                listOf(
                    "rtsExt:x" to "${it.x}",
                    "rtsExt:y" to "${it.y}",
                    "rtsExt:height" to "${it.height}",
                    "rtsExt:width" to "${it.width}",
                    "rtsExt:direction" to it.direction,
                ),
            )
        }
        ext.properties.forEach { (k, v) ->
            element("rtsExt:Properties", listOf("rtsExt:name" to k, "rtsExt:value" to v.ifEmpty { null }))
        }
        ext.unknownElements.forEach { foreign(it) }
        end(name)
    }

    private fun foreign(e: ForeignElement) {
        start(e.name, e.attributes.toList())
        if (e.children.isEmpty() && e.text.isNotEmpty()) xml.characters(e.text.toCharArray(), 0, e.text.length)
        e.children.forEach { foreign(it) }
        end(e.name)
    }

    private fun start(name: String, attributes: List<Pair<String, String>>) {
        val all = AttributesImpl()
        attributes.forEach { (qualified, value) ->
            all.addAttribute(namespaceOf(qualified), localPart(qualified), qualified, "CDATA", value)
        }
        xml.startElement(namespaceOf(name), localPart(name), name, all)
    }

    private fun end(name: String) = xml.endElement(namespaceOf(name), localPart(name), name)

    private companion object {
        /**
         * Declared on the root. A foreign name's prefix is declared where it was read, by an attribute kept with it.
         */
        val NAMESPACES = mapOf("rts" to RTS_NS, "rtsExt" to RTS_EXT_NS, "xsi" to XSI_NS)

        fun namespaceOf(qualified: String): String = NAMESPACES[qualified.substringBefore(':', "")].orEmpty()

        fun localPart(qualified: String): String = qualified.substringAfter(':')
    }
}
