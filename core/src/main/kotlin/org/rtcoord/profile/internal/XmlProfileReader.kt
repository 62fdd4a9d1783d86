package org.rtcoord.profile.internal

import org.rtcoord.profile.ComponentGroup
import org.rtcoord.profile.Condition
import org.rtcoord.profile.ConfigurationSet
import org.rtcoord.profile.ExecutionContext
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.Location
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.Ordering
import org.rtcoord.profile.OrderingKind
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.ProfilePort
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent
import javax.xml.XMLConstants

/** Reads the XML form, as RTSystemEditor and rtsprofile write it; [source] names the file in errors. */
internal class XmlProfileReader(private val source: String) {
    fun read(text: String): RtsProfile {
        val root = XmlElement.parse(text, source)
        if (root.namespace != RTS_NS || root.localName != "RtsProfile") {
            throw ProfileFormatException(source, root.line, "the root element is ${root.qualifiedName}, not rts:RtsProfile in $RTS_NS")
        }
        return Fields(root).run {
            val components = children("Components").map { component(Fields(it)) }
            RtsProfile(
                id = required("id"),
                version = attribute("version") ?: "0.2",
                abstract = attribute("abstract").orEmpty(),
                creationDate = attribute("creationDate").orEmpty(),
                updateDate = attribute("updateDate").orEmpty(),
                components = components,
                groups = children("Groups").map { Fields(it).run { ComponentGroup(attribute("groupID") ?: required("groupId"), children("Members").map { m -> targetComponent(Fields(m)) }, ext()) } },
                dataPortConnectors = children("DataPortConnectors").map { connector(Fields(it), "sourceDataPort", "targetDataPort") },
                servicePortConnectors = children("ServicePortConnectors").map { connector(Fields(it), "sourceServicePort", "targetServicePort") },
                orderings = OrderingKind.entries.mapNotNull { kind -> child(kind.xmlName)?.let { kind to ordering(Fields(it)) } }.toMap(),
                ext = ext(),
            )
        }
    }

    private fun component(f: Fields) = with(f) {
        ProfileComponent(
            id = required("id"),
            pathUri = attribute("pathUri").orEmpty(),
            instanceName = required("instanceName"),
            activeConfigurationSet = attribute("activeConfigurationSet").orEmpty(),
            compositeType = attribute("compositeType") ?: "None",
            isRequired = boolean("isRequired") ?: false,
            dataPorts = children("DataPorts").map { Fields(it).run { ProfilePort(required("name"), ext()) } },
            servicePorts = children("ServicePorts").map { Fields(it).run { ProfilePort(required("name"), ext()) } },
            configurationSets = children("ConfigurationSets").map { set ->
                Fields(set).run {
                    val data = children("ConfigurationData").associate { d -> Fields(d).run { (required("name") to attribute("data").orEmpty()).also { ext() } } }
                    ConfigurationSet(required("id"), data, ext())
                }
            },
            executionContexts = children("ExecutionContexts").map { ec ->
                Fields(ec).run {
                    ExecutionContext(
                        required("id"), attribute("kind") ?: "PERIODIC", double("rate"),
                        children("Participants").map { participant(Fields(it)) }, ext(),
                    )
                }
            },
            participants = children("Participants").map { participant(Fields(it)) },
            ext = ext(),
        )
    }

    /** `<rts:Participants><rts:Participant .../></rts:Participants>`: the wrapper holds one target. */
    private fun participant(f: Fields): TargetComponent = with(f) {
        val inner = child("Participant") ?: throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no rts:Participant")
        targetComponent(Fields(inner)).also { ext() }
    }

    private fun targetComponent(f: Fields) = with(f) {
        TargetComponent(required("componentId"), required("instanceName"), attribute("portName"), attribute("id"), ext())
    }

    private fun connector(f: Fields, sourceName: String, targetName: String) = with(f) {
        fun end(name: String) = targetComponent(Fields(child(name) ?: throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no rts:$name")))
        PortConnector(
            connectorId = attribute("connectorId").orEmpty(),
            name = attribute("name").orEmpty(),
            source = end(sourceName),
            target = end(targetName),
            dataType = attribute("dataType"),
            interfaceType = attribute("interfaceType"),
            dataflowType = attribute("dataflowType"),
            subscriptionType = attribute("subscriptionType"),
            pushInterval = double("pushInterval"),
            transMethod = attribute("transMethod"),
            ext = ext(),
        )
    }

    private fun ordering(f: Fields) = with(f) {
        Ordering(children("targets").map { target(Fields(it)) }, ext())
    }

    private fun target(f: Fields) = with(f) {
        val sequence = int("sequence") ?: 0
        val component = targetComponent(Fields(child("TargetComponent") ?: throw ProfileFormatException(source, element.line, "a target has no rts:TargetComponent")))
        val wait = child("WaitTime")
        val preceding = child("Preceding")
        val condition = when {
            wait != null -> Fields(wait).run { Condition.WaitTime(int("waitTime") ?: 0).also { ext() } }
            preceding != null -> Fields(preceding).run {
                Condition.Preceding(
                    children("PrecedingComponents").map { targetComponent(Fields(it)) },
                    int("timeout") ?: 0,
                    attribute("sendingTiming") ?: "ASYNC",
                ).also { ext() }
            }
            else -> Condition.None
        }
        OrderedTarget(sequence, component, condition, ext())
    }

    /**
     * The attributes and children of one element, each taken at most once, so that [ext] can keep what
     * nothing took.
     */
    private inner class Fields(val element: XmlElement) {
        private val taken = mutableSetOf<Any>()

        fun attribute(name: String, namespace: String = RTS_NS): String? =
            element.attributes.firstOrNull { it.localName == name && (it.namespace == namespace || it.namespace.isEmpty()) }?.also { taken += it }?.value

        fun required(name: String): String =
            attribute(name) ?: throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no rts:$name")

        fun int(name: String): Int? = attribute(name)?.let { it.trim().toIntOrNull() ?: bad(name, it, "an integer") }

        fun double(name: String): Double? = attribute(name)?.let { it.trim().toDoubleOrNull() ?: bad(name, it, "a number") }

        fun boolean(name: String, namespace: String = RTS_NS): Boolean? = attribute(name, namespace)?.let {
            when (it.trim().lowercase()) {
                "true" -> true
                "false" -> false
                else -> bad(name, it, "true or false")
            }
        }

        fun children(name: String, namespace: String = RTS_NS): List<XmlElement> =
            element.children.filter { it.localName == name && it.namespace == namespace }.also { taken.addAll(it) }

        fun child(name: String, namespace: String = RTS_NS): XmlElement? = children(name, namespace).firstOrNull()

        /** The rts_ext data and everything not taken; call it last. */
        fun ext(): Extension {
            val comment = attribute("comment", RTS_EXT_NS)
            val visible = boolean("visible", RTS_EXT_NS)
            val location = child("Location", RTS_EXT_NS)?.let { location(Fields(it)) }
            val properties = children("Properties", RTS_EXT_NS).associate { p -> Fields(p).run { (required("name", RTS_EXT_NS) to attribute("value", RTS_EXT_NS).orEmpty()).also { ext() } } }
            element.attributes.filter { it.namespace == XSI_NS && it.localName == "type" }.forEach { taken += it }
            val unknownAttributes = element.attributes
                .filter { it !in taken && !(it.namespace == XMLConstants.XMLNS_ATTRIBUTE_NS_URI && it.value in STANDARD_NAMESPACES) }
                .associate { it.qualifiedName to it.value }
            val unknownElements = element.children.filter { it !in taken }.map { foreign(it) }
            return Extension(comment, visible, location, properties, unknownAttributes, unknownElements)
        }

        private fun required(name: String, namespace: String): String =
            attribute(name, namespace) ?: throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no $name")

        private fun location(f: Fields) = with(f) {
            fun coordinate(name: String) = attribute(name, RTS_EXT_NS)?.let { it.trim().toIntOrNull() ?: bad(name, it, "an integer") } ?: 0
            Location(coordinate("x"), coordinate("y"), coordinate("width"), coordinate("height"), attribute("direction", RTS_EXT_NS) ?: "RIGHT")
        }

        private fun bad(name: String, value: String, wanted: String): Nothing =
            throw ProfileFormatException(source, element.line, "${element.qualifiedName} $name='$value' is not $wanted")
    }

    private fun foreign(element: XmlElement): ForeignElement = ForeignElement(
        element.qualifiedName,
        element.attributes.associate { it.qualifiedName to it.value },
        element.children.map { foreign(it) },
        if (element.children.isEmpty()) element.text.toString() else "",
    )

    private companion object {
        val STANDARD_NAMESPACES = setOf(RTS_NS, RTS_EXT_NS, XSI_NS)
    }
}
