package org.rtcoord.cli

import org.rtcoord.FsmStatus

/** An FSM's state as `cat` and the live view show it: the state, or why it is not known. */
internal fun FsmStatus.text(): String = state ?: "unknown ($unknownBecause)"
