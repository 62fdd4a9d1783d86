package org.rtcoord.internal

import java.util.concurrent.ConcurrentHashMap
import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.currentCoroutineContext

/**
 * The component reads of one survey ([org.rtcoord.DirectoryNode.survey]), carried in its coroutines' context: a
 * component reached by two paths (its naming context and its manager) is read once, and its manager's listing takes the
 * instance name from that read instead of asking for the profile again.
 */
internal class SurveyReads : AbstractCoroutineContextElement(SurveyReads) {
    private val summaries = ConcurrentHashMap<ComponentObject, CompletableDeferred<ComponentReader.SummaryReading>>()

    /** [component]'s summary in this survey: made by [read] on the first request, shared by the later ones. */
    suspend fun summary(
        component: ComponentObject,
        read: suspend () -> ComponentReader.SummaryReading,
    ): ComponentReader.SummaryReading {
        val mine = CompletableDeferred<ComponentReader.SummaryReading>()
        val earlier =
            summaries.putIfAbsent(component, mine)
                ?: return try {
                    read().also { mine.complete(it) }
                } catch (e: Throwable) {
                    mine.completeExceptionally(e)
                    throw e
                }
        return earlier.await()
    }

    /**
     * [component]'s instance name from its summary in this survey, once that is read; null without one. A read that
     * failed fails this too: asking the component again would wait out a hung one's deadline twice.
     */
    suspend fun instanceName(component: ComponentObject): String? = summaries[component]?.await()?.instanceName

    companion object Key : CoroutineContext.Key<SurveyReads> {
        /** The reads of the survey the caller runs in, or null outside one. */
        suspend fun current(): SurveyReads? = currentCoroutineContext()[Key]
    }
}
