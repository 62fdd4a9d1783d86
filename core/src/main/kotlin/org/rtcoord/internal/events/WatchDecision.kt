package org.rtcoord.internal.events

import kotlin.time.Duration
import org.rtcoord.EventOptions
import org.rtcoord.ObserverFlavour
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode

/** How the last attempt to attach an observer to a component ended. */
internal sealed interface Attachment {
    /** No registration wants pushed events, so none was tried. */
    object NotTried : Attachment

    /** The component took the observer of [flavour]. */
    data class Attached(val flavour: ObserverFlavour) : Attachment

    /** The component advertises neither flavour in `sdo.service.consumer.available_services` ([advertised]). */
    data class NotOffered(val advertised: List<String>) : Attachment

    /** `add_service_profile` answered false for each of [flavours]. */
    data class Refused(val flavours: List<ObserverFlavour>) : Attachment

    /** A call on the way failed: [failure] says which and why. */
    data class Failed(val failure: String) : Attachment
}

/** Why a component whose attachment ended so is not pushed to; null when it is. */
internal val Attachment.whyNotPushed: String?
    get() =
        when (this) {
            Attachment.NotTried -> "no observer was tried"
            is Attachment.Attached -> null
            is Attachment.NotOffered ->
                "it offers no ComponentObserver (sdo.service.consumer.available_services: ${advertised.joinToString().ifEmpty { "none" }})"
            is Attachment.Refused -> "it refused the ${flavours.joinToString(" and the ") { it.label }}"
            is Attachment.Failed -> "attaching an observer failed: $failure"
        }

/**
 * How a component watched by registrations with [options] is watched, after [attachment]; null when nothing asks for
 * it. Registrations in [WatchMode.POLL] are polled, those in [WatchMode.AUTO] polled unless an observer was attached,
 * at the shortest period asked for. An attached observer beats at [heartbeat], the shortest asked for when null.
 */
internal fun decideWatchMethod(
    options: List<EventOptions>,
    attachment: Attachment,
    heartbeat: Duration? = null,
): WatchMethod? {
    if (options.isEmpty()) return null
    val push = options.filter { it.mode != WatchMode.POLL }
    val attached = (attachment as? Attachment.Attached)?.takeIf { push.isNotEmpty() }
    val polled = options.filter { it.mode == WatchMode.POLL || (it.mode == WatchMode.AUTO && attached == null) }
    val period = polled.minOfOrNull { it.pollPeriod }
    return when {
        attached != null -> WatchMethod.Pushed(attached.flavour, heartbeat ?: push.minOf { it.heartbeat }, period)
        push.isEmpty() -> WatchMethod.Polled(period!!, ASKED)
        period != null -> WatchMethod.Polled(period, attachment.whyNotPushed!!)
        else -> WatchMethod.Unwatched(attachment.whyNotPushed!!)
    }
}

private const val ASKED = "polling was asked for"

/** How often the component is read again, whatever else watches it. */
internal val WatchMethod.pollPeriod: kotlin.time.Duration?
    get() =
        when (this) {
            is WatchMethod.Pushed -> pollPeriod
            is WatchMethod.Polled -> period
            is WatchMethod.Unwatched -> null
        }
