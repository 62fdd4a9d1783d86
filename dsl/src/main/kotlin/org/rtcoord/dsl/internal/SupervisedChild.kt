package org.rtcoord.dsl.internal

import org.rtcoord.ComponentNode
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.dsl.ComponentRef
import org.rtcoord.dsl.RestartType

/**
 * What a supervisor knows of one of its components: what to re-create it from and the configuration to restore. Where
 * it is now is not its to know: [node] is what its [name] refers to now, as the run's [Identities] decide, following it
 * through re-creation by the supervisor or by anyone else. Changed only under the supervisor's lock.
 *
 * @property index its place in the declared order.
 */
internal class SupervisedChild(val index: Int, val ref: ComponentRef, val restart: RestartType) {
    /** Its name as the run follows it; set when supervision starts. */
    lateinit var name: FollowedComponent

    /** The component its name refers to now. */
    val node: ComponentNode
        get() = name.node

    /** The supervisor's watch on [node]. */
    var subscription: Subscription? = null

    /** The managers to re-create it through: the one hosting it first, then that one's masters. */
    var managers: List<ManagerNode> = emptyList()

    lateinit var typeName: String
    lateinit var instanceName: String

    /** The active configuration set and its values, as last seen. */
    var configuration: RecordedConfiguration? = null

    /** Set once the supervisor let it go (a temporary or transient component that ended). */
    var left: Boolean = false

    /** What the component answers when asked for its state now. */
    suspend fun status(): ChildStatus =
        try {
            ChildStatus.Up(node.state())
        } catch (e: RtcException) {
            ChildStatus.Gone(e.reason)
        }

    override fun toString(): String = node.path.toString()
}

/** What a supervised component answers when asked for its state. */
internal sealed class ChildStatus {
    /** It answers, in [state]. */
    class Up(val state: LifeCycle) : ChildStatus()

    /** It does not answer, for [reason]. */
    class Gone(val reason: String) : ChildStatus()
}

/** A configuration set id and its parameter values. */
internal data class RecordedConfiguration(val set: String, val values: Map<String, String>)
