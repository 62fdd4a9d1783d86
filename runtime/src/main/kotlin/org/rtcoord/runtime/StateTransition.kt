package org.rtcoord.runtime

import RTC.LifeCycleState

/**
 * One lifecycle transition a component made in execution context [handle], as the context made it: the ground truth
 * that tests compare a coordinator's events with. [at] is `System.nanoTime()` at the time.
 */
public data class StateTransition(val handle: Int, val from: LifeCycleState, val to: LifeCycleState, val at: Long)
