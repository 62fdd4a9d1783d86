package org.rtcoord.internal

import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcTree
import org.rtcoord.internal.events.ListenerFailures

/**
 * The tree's scope: its threads and its job. The dsl's coordinators run in a child of it, on the tree's threads rather
 * than kotlinx's shared ones (which outlive an OSGi bundle), and they end before those threads do. Public for the dsl
 * only.
 */
@InternalRtcoordApi public fun RtcTree.treeScope(): CoroutineScope = core.scope

/**
 * The tree's clock: the robot's time, [org.rtcoord.TreeConfig.speed] times as fast as the host's. What the dsl's rules
 * and the simulation's scenarios measure, as the tree's own waits follow it. Public for the dsl and the simulation
 * only.
 */
@InternalRtcoordApi public fun RtcTree.treeTime(): TimeSource.WithComparableMarks = core.time

/**
 * Tells the tree's [org.rtcoord.ListenerFailureHandler] that [listener] threw [error] on [event], or that its executor
 * refused the task: the dsl's Java facade reports its listeners' failures where the tree's own listeners' go. Public
 * for the dsl only.
 */
@InternalRtcoordApi
public fun RtcTree.reportListenerFailure(listener: Any, event: Any, error: Throwable) {
    checkNotNull(core.scope.coroutineContext[ListenerFailures]) { "a tree's scope holds its listener failure handler" }
        .report(listener, event, error)
}
