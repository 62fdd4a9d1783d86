package org.rtcoord.dsl.internal

import kotlinx.coroutines.CancellationException

/**
 * Runs [block]; an [Exception] it throws is handed to [failed], whose result is returned instead (or which throws). A
 * [CancellationException] goes on: a cancelled coroutine must end, not count its cancellation as a failure. Errors go
 * on too.
 */
internal inline fun <T> catchFailure(block: () -> T, failed: (Exception) -> T): T =
    try {
        block()
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        failed(e)
    }
