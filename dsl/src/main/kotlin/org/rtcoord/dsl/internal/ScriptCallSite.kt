package org.rtcoord.dsl.internal

import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.EmptyCoroutineContext
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.withContext

/**
 * Where a handler last called into the DSL from its script: the script's frames then, innermost first. A failure that
 * surfaces after the DSL suspended (a CORBA call that failed) carries only the frames of the code that resumed, none of
 * the script's: this is where such a failure was asked for.
 */
internal class ScriptCallSite : AbstractCoroutineContextElement(ScriptCallSite) {
    @Volatile private var frames: List<StackTraceElement> = emptyList()

    private fun mark() {
        frames = walker.walk { stack ->
            stack.filter { isScriptFrame(it.fileName, it.lineNumber) }.map { it.toStackTraceElement() }.toList()
        }
    }

    companion object Key : CoroutineContext.Key<ScriptCallSite> {
        private val walker = StackWalker.getInstance()

        /**
         * Records the caller's script frames, when a handler runs in [tracking]; every entry to the DSL that may
         * suspend calls it first.
         */
        suspend fun mark() {
            currentCoroutineContext()[ScriptCallSite]?.mark()
        }

        /**
         * Runs [block], in [context] too (one switch of context for both); a failure without frames of the script gets
         * those of its last call into the DSL, as a suppressed [CalledFromScript].
         */
        suspend fun <T> tracking(context: CoroutineContext = EmptyCoroutineContext, block: suspend () -> T): T {
            val site = ScriptCallSite()
            return catchFailure({ withContext(site + context) { block() } }) { e ->
                if (scriptFrames(e).isEmpty() && site.frames.isNotEmpty())
                    e.addSuppressed(CalledFromScript(site.frames))
                throw e
            }
        }
    }
}

/**
 * Where in its script a handler called the DSL action that failed: its stack trace is the script's frames at that call.
 */
internal class CalledFromScript(frames: List<StackTraceElement>) :
    Exception("called from the script", null, false, true) {
    init {
        stackTrace = frames.toTypedArray()
    }
}

/** Whether a frame of [fileName] at [line] is a line of a coordinator script (bridges the compiler made have none). */
internal fun isScriptFrame(fileName: String?, line: Int): Boolean = fileName?.endsWith(".coord.kts") == true && line > 0

/**
 * The script frames of [error], innermost first: its own or its causes', else where it was called from
 * ([CalledFromScript]).
 */
internal fun scriptFrames(error: Throwable): List<StackTraceElement> {
    val chain = generateSequence(error) { it.cause }.take(16).toList()
    chain
        .firstNotNullOfOrNull { e ->
            e.stackTrace.filter { isScriptFrame(it.fileName, it.lineNumber) }.takeIf { it.isNotEmpty() }
        }
        ?.let {
            return it
        }
    return chain
        .flatMap { it.suppressed.asList() }
        .filterIsInstance<CalledFromScript>()
        .firstOrNull()
        ?.stackTrace
        ?.asList()
        .orEmpty()
}
