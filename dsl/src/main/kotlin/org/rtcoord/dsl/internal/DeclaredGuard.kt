package org.rtcoord.dsl.internal

import org.rtcoord.RtcEvent
import org.rtcoord.dsl.Guard
import org.rtcoord.dsl.Reaction

/**
 * A rule's guard (a function type with a receiver cannot be a supertype: the same type without it is) with the [line]
 * of the script its `where` is written on (null for one declared in code): what lets `check` show the guard's own text.
 */
internal class DeclaredGuard(private val guard: Guard, val line: Int?) : suspend (Reaction, RtcEvent) -> Boolean {
    override suspend fun invoke(reaction: Reaction, event: RtcEvent): Boolean = guard(reaction, event)

    companion object {
        private val walker = StackWalker.getInstance()

        /**
         * [guard], with the line of the script that declares it: the innermost coordinator script frame of the caller.
         */
        fun of(guard: Guard): Guard =
            DeclaredGuard(
                guard,
                walker.walk { frames ->
                    frames
                        .filter { isScriptFrame(it.fileName, it.lineNumber) }
                        .findFirst()
                        .map { it.lineNumber }
                        .orElse(null)
                },
            )
    }
}
