package org.rtcoord.dsl

/**
 * Marks the DSL's receivers, so that inside a rule's handler the outer script's registration functions (`on`, `every`)
 * cannot be called by accident through an implicit outer receiver.
 */
@DslMarker public annotation class RtcDsl
