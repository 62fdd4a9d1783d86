package org.rtcoord.dsl

import org.rtcoord.RtcPath

/**
 * A connection a supervisor makes again when one of its components is re-created: its ports in the
 * connector's order (the first one connects), name and properties. [id] is the connector's id now.
 */
internal class RecordedConnection(var id: String, val name: String, properties: Map<String, String>, val ends: List<End>) {
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

    /**
     * The properties to connect with: the endpoints the ports published during the first connection
     * (`dataport.corba_cdr.*` IORs, `port.*` service references) point at the dead component and would
     * override the new ones.
     */
    val properties: Map<String, String> = properties.filterKeys { !it.startsWith("dataport.corba_cdr.") && !it.startsWith("port.") }

    fun involves(child: SupervisedChild): Boolean = ends.any { it is End.Supervised && it.child === child }

    /** The supervised components at its ends. */
    val children: List<SupervisedChild> get() = ends.filterIsInstance<End.Supervised>().map { it.child }.distinct()

    override fun toString(): String = ends.joinToString(" -> ")
}
