package org.rtcoord.profile.internal

/** The connector property rtshell stores an end's component path in. */
internal const val COMPONENT_PATH_ID = "COMPONENT_PATH_ID"

/** The connector properties that name the old connection's object references: not restored, not compared. */
internal val STALE_REFERENCES = setOf(
    "dataport.corba_cdr.inport_ior", "dataport.corba_cdr.inport_ref",
    "dataport.corba_cdr.outport_ior", "dataport.corba_cdr.outport_ref",
)
