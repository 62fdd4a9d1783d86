package org.rtcoord.internal

import RTC.ReturnCode_t
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.resume
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.runInterruptible
import kotlinx.coroutines.suspendCancellableCoroutine
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.BadParameterException
import org.rtcoord.NotFoundException
import org.rtcoord.OperationFailedException
import org.rtcoord.OperationUnsupportedException
import org.rtcoord.PreconditionNotMetException
import org.rtcoord.RtcException
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException

/**
 * Runs blocking CORBA calls, [concurrency] at a time, turning every failure into an [RtcException] about the call's
 * subject. The tree's own ORB times every call out at the tree's deadline; a coroutine backstop ends the wait at a
 * call's own (shorter) deadline, and is the only guard on an ORB a host application supplied ([orbEnforcesDeadline]
 * false).
 *
 * A call runs on the caller's thread when the caller is on [dispatcher], as discovery and the component monitors are: a
 * call costs no thread hand-over there, and hand-overs cost discovery more than the calls themselves. A call made for a
 * caller who may give up ([AbandonableCalls]: the Java facades' futures and blocking calls) blocks a thread of its own
 * instead: JacORB ignores interrupts until the call times out, so the caller returns at once and frees its slot, and
 * the one thread is left to the ORB's timeout. One hung object holds at most the threads of the calls made to it.
 */
internal class Remote(
    concurrency: Int,
    val defaultDeadline: Duration,
    private val orbEnforcesDeadline: Boolean,
    private val threads: TreeThreads,
) {
    private val slots = Semaphore(concurrency)

    /** Where calls run, [concurrency] at a time, and work that makes many calls (discovery, reading a component). */
    val dispatcher: CoroutineDispatcher = threads.calls.limitedParallelism(concurrency)

    /**
     * Where the calling coroutine's calls and the work that makes them run: its [BackgroundCalls]' few threads under
     * the tree's periodic listings, else [dispatcher].
     */
    suspend fun callDispatcher(): CoroutineDispatcher =
        currentCoroutineContext()[BackgroundCalls]?.dispatcher ?: dispatcher

    /**
     * Runs [block] once one of the tree's call slots is free; the deadline counts from then, so calls queued behind a
     * large discovery do not expire before they are sent.
     */
    suspend fun <T> call(subject: String, operation: String, deadline: Duration? = null, block: () -> T): T {
        val limit = deadline ?: defaultDeadline
        val outcome =
            slots.withPermit {
                if (orbEnforcesDeadline && limit >= defaultDeadline) {
                    attempt(subject, operation, limit, block)
                } else {
                    withTimeoutOrNull(limit + BACKSTOP) { attempt(subject, operation, limit, block) }
                }
            } ?: throw TimedOutException(subject, operation, limit.inWholeMilliseconds)
        return outcome.getOrThrow()
    }

    private suspend fun <T> attempt(subject: String, operation: String, limit: Duration, block: () -> T): Result<T> {
        fun run(): Result<T> =
            try {
                Result.success(block())
            } catch (e: Exception) {
                Result.failure(translate(e, subject, operation, limit))
            }
        if (currentCoroutineContext()[AbandonableCalls] == null)
            return withContext(callDispatcher()) { runInterruptible { run() } }
        return suspendCancellableCoroutine { waiting ->
            // Resuming is ignored when the caller has given up.
            val running = threads.submit { waiting.resume(run()) }
            waiting.invokeOnCancellation { running.cancel(true) }
        }
    }

    private companion object {
        val BACKSTOP = 200.milliseconds
    }
}

/** Marks the calls made for a caller who may give up waiting: each blocks a thread of its own (see [Remote]). */
internal object AbandonableCalls : CoroutineContext.Element, CoroutineContext.Key<AbandonableCalls> {
    override val key: CoroutineContext.Key<*>
        get() = this
}

/** Throws the error a `ReturnCode_t` other than `RTC_OK` stands for. */
internal fun ReturnCode_t.orFail(subject: String, operation: String, detail: String? = null) {
    when (this) {
        ReturnCode_t.RTC_OK -> Unit
        ReturnCode_t.PRECONDITION_NOT_MET ->
            throw PreconditionNotMetException(subject, operation, detail ?: "PRECONDITION_NOT_MET")
        ReturnCode_t.BAD_PARAMETER -> throw BadParameterException(subject, operation, detail ?: "BAD_PARAMETER")
        ReturnCode_t.UNSUPPORTED -> throw OperationUnsupportedException(subject, operation)
        else -> throw OperationFailedException(subject, operation, name(), detail)
    }
}

/** The IDL name of a return code (`RTC_ERROR`, ...). */
internal fun ReturnCode_t.name(): String =
    listOf("RTC_OK", "RTC_ERROR", "BAD_PARAMETER", "UNSUPPORTED", "OUT_OF_RESOURCES", "PRECONDITION_NOT_MET").getOrElse(
        value()
    ) {
        "code ${value()}"
    }

private fun translate(e: Exception, subject: String, operation: String, limit: Duration): Exception =
    when (e) {
        is RtcException -> e
        is org.omg.CORBA.TIMEOUT -> TimedOutException(subject, operation, limit.inWholeMilliseconds)
        is org.omg.CORBA.TRANSIENT,
        is org.omg.CORBA.COMM_FAILURE,
        is org.omg.CORBA.OBJECT_NOT_EXIST,
        is org.omg.CORBA.NO_RESPONSE,
        is org.omg.CORBA.INV_OBJREF -> UnreachableException(subject, e)
        is org.omg.CORBA.BAD_OPERATION,
        is org.omg.CORBA.NO_IMPLEMENT -> OperationUnsupportedException(subject, operation)
        is org.omg.CosNaming.NamingContextPackage.NotFound -> NotFoundException(subject, "not bound")
        is _SDOPackage.InvalidParameter -> BadParameterException(subject, operation, e.description)
        is _SDOPackage.InterfaceNotImplemented -> OperationUnsupportedException(subject, operation)
        is _SDOPackage.NotAvailable -> OperationFailedException(subject, operation, "NotAvailable", e.description)
        is _SDOPackage.InternalError -> OperationFailedException(subject, operation, "InternalError", e.description)
        is org.omg.CORBA.SystemException ->
            OperationFailedException(subject, operation, e.javaClass.simpleName, e.message)
        is org.omg.CORBA.UserException -> OperationFailedException(subject, operation, e.javaClass.simpleName)
        is InterruptedException -> TimedOutException(subject, operation, limit.inWholeMilliseconds)
        else -> e
    }
