package org.rtcoord.profile.internal

import javax.xml.XMLConstants
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.Location
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfile

/** Reads the XML form, as RTSystemEditor and rtsprofile write it; [source] names the file in errors. */
internal class XmlProfileReader(private val source: String) {
    fun read(text: String): RtsProfile {
        val root = XmlElement.parse(text, source)
        if (root.namespace != RTS_NS || root.localName != "RtsProfile") {
            throw ProfileFormatException(
                source,
                root.line,
                "the root element is ${root.qualifiedName}, not rts:RtsProfile in $RTS_NS",
            )
        }
        return ProfileDecoder.decode(Tree(root))
    }

    /**
     * One element: keys name its attributes, or its children by their element names (capitalised, as the schema has
     * most).
     */
    private inner class Tree(private val element: XmlElement) : ProfileTree {
        private val taken = mutableSetOf<Any>()

        override fun text(key: String): String? = attribute(key, RTS_NS)

        override fun child(key: String): ProfileTree? = elements(elementName(key), RTS_NS).firstOrNull()?.let(::Tree)

        override fun list(key: String): List<ProfileTree> = elements(elementName(key), RTS_NS).map(::Tree)

        override fun date(key: String): String = text(key).orEmpty()

        override fun missing(key: String): Nothing =
            throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no rts:$key")

        override fun missingChild(key: String): Nothing = missing(elementName(key))

        override fun invalid(key: String, value: String, wanted: String): Nothing =
            throw ProfileFormatException(source, element.line, "${element.qualifiedName} $key='$value' is not $wanted")

        override fun ext(): Extension {
            val comment = attribute("comment", RTS_EXT_NS)
            val visible = attribute("visible", RTS_EXT_NS)?.let { booleanOf("visible", it) }
            val location = elements("Location", RTS_EXT_NS).firstOrNull()?.let { Tree(it).location() }
            val properties =
                elements("Properties", RTS_EXT_NS).associate { p ->
                    Tree(p).run { (extAttribute("name") to attribute("value", RTS_EXT_NS).orEmpty()).also { ext() } }
                }
            element.attributes.filter { it.namespace == XSI_NS && it.localName == "type" }.forEach { taken += it }
            val unknownAttributes =
                element.attributes
                    .filter {
                        it !in taken &&
                            !(it.namespace == XMLConstants.XMLNS_ATTRIBUTE_NS_URI && it.value in STANDARD_NAMESPACES)
                    }
                    .associate { it.qualifiedName to it.value }
            val unknownElements = element.children.filter { it !in taken }.map(::foreign)
            return Extension(comment, visible, location, properties, unknownAttributes, unknownElements)
        }

        private fun attribute(name: String, namespace: String): String? =
            element.attributes
                .firstOrNull { it.localName == name && (it.namespace == namespace || it.namespace.isEmpty()) }
                ?.also { taken += it }
                ?.value

        private fun elements(name: String, namespace: String): List<XmlElement> =
            element.children.filter { it.localName == name && it.namespace == namespace }.also { taken.addAll(it) }

        private fun extAttribute(name: String): String =
            attribute(name, RTS_EXT_NS)
                ?: throw ProfileFormatException(source, element.line, "${element.qualifiedName} has no $name")

        private fun location(): Location {
            fun coordinate(name: String) =
                attribute(name, RTS_EXT_NS)?.let { it.trim().toIntOrNull() ?: invalid(name, it, "an integer") } ?: 0
            return Location(
                coordinate("x"),
                coordinate("y"),
                coordinate("width"),
                coordinate("height"),
                attribute("direction", RTS_EXT_NS) ?: "RIGHT",
            )
        }
    }

    private fun foreign(element: XmlElement): ForeignElement =
        ForeignElement(
            element.qualifiedName,
            element.attributes.associate { it.qualifiedName to it.value },
            element.children.map(::foreign),
            if (element.children.isEmpty()) element.text.toString() else "",
        )

    private companion object {
        val STANDARD_NAMESPACES = setOf(RTS_NS, RTS_EXT_NS, XSI_NS)

        /** The keys that name elements the schema spells in lower case; every other element is capitalised. */
        val LOWER_CASE_ELEMENTS =
            setOf("targets", "sourceDataPort", "targetDataPort", "sourceServicePort", "targetServicePort")

        fun elementName(key: String): String =
            if (key in LOWER_CASE_ELEMENTS) key else key.replaceFirstChar(Char::uppercaseChar)
    }
}
