package org.rtcoord.profile.internal

/** The connector property rtshell stores an end's component path in. */
internal const val COMPONENT_PATH_ID = "COMPONENT_PATH_ID"

/** The connector properties that name the old connection's object references: not restored, not compared. */
private val STALE_REFERENCES =
    setOf(
        "dataport.corba_cdr.inport_ior",
        "dataport.corba_cdr.inport_ref",
        "dataport.corba_cdr.outport_ior",
        "dataport.corba_cdr.outport_ref",
    )

/**
 * [properties] without the object references the old connection's ports published: [STALE_REFERENCES] and every value
 * that is an IOR, such as the `port.<type>.<instance>` a service port publishes for each interface it provides. They
 * die with the connection.
 */
internal fun withoutReferences(properties: Map<String, String>): Map<String, String> =
    properties.filter { (key, value) ->
        key !in STALE_REFERENCES && !value.startsWith("IOR:")
    }
