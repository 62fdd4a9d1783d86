package org.rtcoord.profile.internal

import java.io.StringReader
import javax.xml.XMLConstants
import javax.xml.stream.XMLInputFactory
import javax.xml.stream.XMLStreamConstants
import javax.xml.stream.XMLStreamException

internal const val RTS_NS = "http://www.openrtp.org/namespaces/rts"
internal const val RTS_EXT_NS = "http://www.openrtp.org/namespaces/rts_ext"
internal const val XSI_NS = XMLConstants.W3C_XML_SCHEMA_INSTANCE_NS_URI

/** An XML attribute with its namespace and the name as written. */
internal data class XmlAttribute(
    val namespace: String,
    val localName: String,
    val qualifiedName: String,
    val value: String,
)

/** An XML element as read, with the line it starts on, so errors can say where. */
internal class XmlElement(
    val namespace: String,
    val localName: String,
    val qualifiedName: String,
    val attributes: List<XmlAttribute>,
    val line: Int,
) {
    val children = mutableListOf<XmlElement>()
    val text = StringBuilder()

    companion object {
        /** Parses [text] into its root element; DTDs and external entities are refused. */
        fun parse(text: String, source: String): XmlElement {
            val factory =
                XMLInputFactory.newFactory().apply {
                    setProperty(XMLInputFactory.SUPPORT_DTD, false)
                    setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false)
                    setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, true)
                }
            val reader =
                try {
                    factory.createXMLStreamReader(StringReader(text))
                } catch (e: XMLStreamException) {
                    throw formatError(source, e)
                }
            val open = ArrayDeque<XmlElement>()
            var root: XmlElement? = null
            try {
                while (reader.hasNext()) {
                    when (reader.next()) {
                        XMLStreamConstants.START_ELEMENT -> {
                            val declarations =
                                (0 until reader.namespaceCount).map { i ->
                                    val prefix = reader.getNamespacePrefix(i)
                                    XmlAttribute(
                                        XMLConstants.XMLNS_ATTRIBUTE_NS_URI,
                                        prefix ?: "",
                                        if (prefix.isNullOrEmpty()) "xmlns" else "xmlns:$prefix",
                                        reader.getNamespaceURI(i),
                                    )
                                }
                            val attributes =
                                (0 until reader.attributeCount).map { i ->
                                    val name = reader.getAttributeName(i)
                                    XmlAttribute(
                                        name.namespaceURI ?: "",
                                        name.localPart,
                                        qualified(name.prefix, name.localPart),
                                        reader.getAttributeValue(i),
                                    )
                                }
                            val element =
                                XmlElement(
                                    reader.namespaceURI ?: "",
                                    reader.localName,
                                    qualified(reader.prefix, reader.localName),
                                    declarations + attributes,
                                    reader.location.lineNumber,
                                )
                            open.lastOrNull()?.children?.add(element)
                            if (root == null) root = element
                            open.addLast(element)
                        }
                        XMLStreamConstants.END_ELEMENT -> open.removeLast()
                        XMLStreamConstants.CHARACTERS,
                        XMLStreamConstants.CDATA -> open.lastOrNull()?.text?.append(reader.text)
                    }
                }
            } catch (e: XMLStreamException) {
                throw formatError(source, e)
            }
            return root ?: throw org.rtcoord.profile.ProfileFormatException(source, 0, "no root element")
        }

        private fun qualified(prefix: String?, local: String) = if (prefix.isNullOrEmpty()) local else "$prefix:$local"

        private fun formatError(source: String, e: XMLStreamException) =
            org.rtcoord.profile.ProfileFormatException(
                source,
                e.location?.lineNumber ?: 0,
                "not well-formed XML: ${e.message?.substringAfter("Message: ")?.trim() ?: e.toString()}",
            )
    }
}
