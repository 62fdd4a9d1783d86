@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.leaky

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.emptyFlow
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** Every kind of leak JavaReach must find, for `JavaSurfaceTest`: none of it is rtcoord's API. */
public open class Leaky internal constructor(private val size: Int) : ValueObject() {
    public constructor() : this(0)

    internal val count: Int
        get() = size

    public suspend fun await(): Int = size

    public fun state(): RTC.LifeCycleState = RTC.LifeCycleState.ACTIVE_STATE

    public val flow: Flow<Int> = emptyFlow()

    public override fun fields(): ValueFields = ValueFields("size" to size)

    public companion object {
        public fun make(): Leaky = Leaky()
    }
}

/** An internal class: public to javac. */
internal class Hidden
