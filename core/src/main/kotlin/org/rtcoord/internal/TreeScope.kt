package org.rtcoord.internal

import kotlinx.coroutines.CoroutineScope
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcTree

/**
 * The tree's scope: its threads and its job. The dsl's coordinators run in a child of it, on the tree's
 * threads rather than kotlinx's shared ones (which outlive an OSGi bundle), and they end before those
 * threads do. Public for the dsl only.
 */
@InternalRtcoordApi
public fun RtcTree.treeScope(): CoroutineScope = core.scope
