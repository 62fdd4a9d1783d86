package org.rtcoord.dsl.internal

import org.rtcoord.RtcPath

/**
 * A connection a supervisor makes again when one of its components is re-created: its ports in the connector's order
 * (the first one connects), name and properties. [id] is the connector's id now.
 */
internal class RecordedConnection(
    var id: String,
    val name: String,
    properties: Map<String, String>,
    val ends: List<End>,
) {
    /** One port of the connection. */
    sealed class End {
        /** A port of a supervised component, wherever that component is now. */
        class Supervised(val child: SupervisedChild, val port: String) : End() {
            override fun toString(): String = child.node.path.withPort(port).toString()
        }

        /** A port of a component the supervisor does not watch, at [path]. */
        class External(val path: RtcPath) : End() {
            override fun toString(): String = path.toString()
        }
    }

    /** The properties to connect with (see [reusableProperties]). */
    val properties: Map<String, String> = reusableProperties(properties)

    /** Whether [other] connects the same ports, in the same order. */
    fun joinsSamePorts(other: RecordedConnection): Boolean =
        ends.map { it.toString() } == other.ends.map { it.toString() }

    fun involves(child: SupervisedChild): Boolean = ends.any { it is End.Supervised && it.child === child }

    /** The supervised components at its ends. */
    val children: List<SupervisedChild>
        get() = ends.filterIsInstance<End.Supervised>().map { it.child }.distinct()

    override fun toString(): String = ends.joinToString(" -> ")
}

/**
 * The properties of connector [properties] a new connection between the same ports can reuse: the endpoints the ports
 * published for the old one (`dataport.corba_cdr.*` IORs, `port.*` service references) may point at a dead component
 * and would override the new ones.
 */
internal fun reusableProperties(properties: Map<String, String>): Map<String, String> = properties.filterKeys {
    !it.startsWith("dataport.corba_cdr.") && !it.startsWith("port.")
}
