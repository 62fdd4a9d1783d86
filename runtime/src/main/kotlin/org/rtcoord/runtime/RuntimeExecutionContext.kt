package org.rtcoord.runtime

import RTC.ExecutionContextProfile
import RTC.ExecutionContextService
import RTC.ExecutionContextServiceHelper
import RTC.ExecutionContextServicePOA
import RTC.ExecutionKind
import RTC.LifeCycleState
import RTC.LightweightRTObject
import RTC.ReturnCode_t
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.ScheduledFuture
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException
import kotlin.concurrent.thread
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.rtcoord.idl.ObjectIdentity

/**
 * An execution context of the kind [spec] says (reported by `get_kind` and its profile), periodic whatever its kind: it
 * holds the lifecycle state of each participant and runs their behaviour at its rate. Transitions follow OpenRTM:
 * activate from INACTIVE, deactivate from ACTIVE, reset from ERROR. As in OpenRTM's state machine, a transition's
 * callbacks and the hints they raise come before the new state shows: a state read meanwhile, which never waits for a
 * transition, finds the old one. A failing `on_execute` aborts the component: `on_deactivated` runs (INACTIVE is
 * announced if it succeeds), then `on_aborting` (ERROR is announced), and the component is in ERROR. What
 * `on_deactivated` returns changes nothing else: a deactivation always ends INACTIVE, announced only when the callback
 * succeeded. A failing `on_activated` sends the component to ERROR. A reset whose `on_reset` fails leaves the component
 * in ERROR, announces nothing and answers `RTC_ERROR` once [transitionTimeout] has passed, as OpenRTM's synchronous
 * reset waits that long for the component to leave ERROR.
 *
 * A participant whose transition callbacks are slow ([RuntimeComponent.slowTransitions]) keeps its old state while they
 * run; a call that outlasts [transitionTimeout] answers `RTC_ERROR`, and the new state shows when the callback returns,
 * as OpenRTM's synchronous transitions do.
 *
 * An ACTIVE participant whose execution hangs ([RuntimeComponent.hangExecution]) holds the context's thread as a hung
 * `on_execute` holds OpenRTM's: no participant executes any more, and a transition asked of the context is never made
 * (OpenRTM's thread makes them), so the call answers `RTC_ERROR` after [transitionTimeout] with the state unchanged.
 * States are still answered at once.
 */
internal class RuntimeExecutionContext(
    private val runtime: RuntimeProcess,
    private val owner: RuntimeComponent,
    private val spec: ContextSpec,
) : ExecutionContextServicePOA() {
    /** The implementation it stands for, as its profile's `type` property names it. */
    val typeName: String
        get() = spec.typeName

    private class Participant(val component: RuntimeComponent, val handle: Int) {
        @Volatile var state: LifeCycleState = LifeCycleState.INACTIVE_STATE
    }

    private val lock = Any()

    /**
     * How long a synchronous transition waits for the context's thread to make it: OpenRTM's default
     * `transition_timeout`, which `activation_timeout`, `deactivation_timeout` and `reset_timeout` take.
     */
    val transitionTimeout = 500.milliseconds
    private val participants = LinkedHashMap<RuntimeComponent, Participant>()

    /** The participants by their reference's identity, looked up without the lock a transition holds. */
    private val byIdentity = ConcurrentHashMap<String, Participant>()
    private var rate = spec.rate

    /**
     * The profile's properties: the options OpenRTM-aist creates a context with (`RTObject.getInheritedECOptions` then
     * `exec_cxt.periodic.*`, copied by `ExecutionContextBase.init`), with its default configuration's values, its
     * implementation's name and the rate as the component's `exec_cxt.periodic.rate` gives it; `set_rate` leaves them
     * as they are, as OpenRTM-aist does.
     */
    private val properties =
        linkedMapOf(
            "sync_transition" to "YES",
            "transition_timeout" to "0.5",
            "type" to spec.typeName,
            "rate" to spec.rate.toString(),
        )
    private var ticker: ScheduledFuture<*>? = null

    /** The participant whose execution has not returned: the context's thread is stuck in it. */
    private var stuckIn: RuntimeComponent? = null

    /** Whether the thread is stuck in a participant's hung execution. */
    val isStuck: Boolean
        get() = synchronized(lock) { stuckIn != null }

    /** How many periods the context has run so far, stuck ones included. */
    @Volatile
    var periods: Long = 0
        private set

    lateinit var ref: ExecutionContextService
        private set

    fun activate(orb: RuntimeOrb) {
        ref = ExecutionContextServiceHelper.narrow(orb.activate(this))
    }

    /** Makes [component] a participant known to it as [handle], INACTIVE. */
    fun join(component: RuntimeComponent, handle: Int) =
        synchronized(lock) {
            val participant = Participant(component, handle)
            participants[component] = participant
            byIdentity[component.identity] = participant
        }

    /** Drops [component] whatever its state: it is exiting. */
    fun leave(component: RuntimeComponent) =
        synchronized(lock) {
            if (stuckIn === component) stuckIn = null
            byIdentity.remove(component.identity)
            participants
                .remove(component)
                ?.takeIf { it.state == LifeCycleState.ACTIVE_STATE }
                ?.let {
                    component.perform(it.handle) { rtc -> onDeactivated(rtc) }
                }
        }

    fun stateOf(component: RuntimeComponent): LifeCycleState =
        byIdentity[component.identity]?.state ?: LifeCycleState.CREATED_STATE

    /**
     * The participant [comp] refers to. Only this context's participants are looked at, as OpenRTM's contexts do: a
     * search through every component of the process made listing a 1000-component system quadratic in the runtime.
     */
    private fun participantOf(comp: LightweightRTObject?): Participant? =
        comp?.let(ObjectIdentity::of)?.let(byIdentity::get)

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream {
        owner.gate.pass()
        return super._invoke(method, input, handler)
    }

    override fun is_running(): Boolean = synchronized(lock) { ticker != null }

    override fun start(): ReturnCode_t =
        synchronized(lock) {
            if (ticker != null) return ReturnCode_t.PRECONDITION_NOT_MET
            schedule()
            announce { "STARTUP:${it.handle}" }
            ReturnCode_t.RTC_OK
        }

    override fun stop(): ReturnCode_t =
        synchronized(lock) {
            val running = ticker ?: return ReturnCode_t.PRECONDITION_NOT_MET
            running.cancel(false)
            ticker = null
            announce { "SHUTDOWN:${it.handle}" }
            ReturnCode_t.RTC_OK
        }

    override fun get_rate(): Double = synchronized(lock) { rate }

    override fun set_rate(rate: Double): ReturnCode_t =
        synchronized(lock) {
            if (!(rate > 0.0)) return ReturnCode_t.BAD_PARAMETER
            this.rate = rate
            ticker?.let {
                it.cancel(false)
                schedule()
            }
            announce { "RATE_CHANGED:${it.handle}" }
            ReturnCode_t.RTC_OK
        }

    override fun add_component(comp: LightweightRTObject?): ReturnCode_t {
        val component = runtime.componentOf(comp) ?: return ReturnCode_t.BAD_PARAMETER
        if (synchronized(lock) { component in participants }) return ReturnCode_t.PRECONDITION_NOT_MET
        val handle = component.attach(this)
        join(component, handle)
        component.observers.raise(StatusKind.EC_STATUS, "ATTACHED:$handle")
        return ReturnCode_t.RTC_OK
    }

    override fun remove_component(comp: LightweightRTObject?): ReturnCode_t {
        val component = participantOf(comp)?.component ?: return ReturnCode_t.BAD_PARAMETER
        val participant =
            synchronized(lock) {
                val participant = participants[component] ?: return ReturnCode_t.BAD_PARAMETER
                if (participant.state == LifeCycleState.ACTIVE_STATE || component === owner)
                    return ReturnCode_t.PRECONDITION_NOT_MET
                byIdentity.remove(component.identity)
                participants.remove(component)
            }
        component.detach(participant!!.handle)
        component.observers.raise(StatusKind.EC_STATUS, "DETACHED:${participant.handle}")
        return ReturnCode_t.RTC_OK
    }

    override fun activate_component(comp: LightweightRTObject?): ReturnCode_t =
        transition(comp, from = LifeCycleState.INACTIVE_STATE, to = LifeCycleState.ACTIVE_STATE) { onActivated(it) }

    override fun deactivate_component(comp: LightweightRTObject?): ReturnCode_t =
        transition(comp, from = LifeCycleState.ACTIVE_STATE, to = LifeCycleState.INACTIVE_STATE) { onDeactivated(it) }

    override fun reset_component(comp: LightweightRTObject?): ReturnCode_t {
        val component = participantOf(comp)?.component
        var resetFailed = false
        val code =
            transition(comp, from = LifeCycleState.ERROR_STATE, to = LifeCycleState.INACTIVE_STATE) { rtc ->
                // The fault is over once a reset succeeds, however long after the call answered.
                (component?.isBroken != true && onReset(rtc)).also {
                    resetFailed = !it
                    if (it) component?.clearFailure()
                }
            }
        // Outside the lock: the context keeps running its other participants meanwhile.
        if (resetFailed) Thread.sleep(runtime.onHost(transitionTimeout).inWholeMilliseconds)
        return code
    }

    // OpenRTM's StateMachine.getState takes only its own short lock: it answers during a transition.
    override fun get_component_state(comp: LightweightRTObject?): LifeCycleState =
        participantOf(comp)?.state ?: LifeCycleState.CREATED_STATE

    override fun get_kind(): ExecutionKind = spec.kind.idl

    override fun get_profile(): ExecutionContextProfile =
        synchronized(lock) {
            ExecutionContextProfile(
                spec.kind.idl,
                rate,
                owner.ref,
                participants.keys.map { it.ref }.toTypedArray(),
                properties.map { (name, value) -> owner.nameValue(name, value) }.toTypedArray(),
            )
        }

    /** Stops ticking; the owner is exiting. */
    fun shutdown() =
        synchronized(lock) {
            ticker?.cancel(false)
            ticker = null
        }

    private fun transition(
        comp: LightweightRTObject?,
        from: LifeCycleState,
        to: LifeCycleState,
        action: Behaviour.(ComponentContext) -> Boolean,
    ): ReturnCode_t {
        val component = participantOf(comp)?.component ?: return ReturnCode_t.BAD_PARAMETER
        val callbackTime = component.transitionCallbackTime
        if (!callbackTime.isPositive()) return transition(component, from, to, action)
        synchronized(lock) {
            val participant = participants[component] ?: return ReturnCode_t.BAD_PARAMETER
            if (participant.state != from) return ReturnCode_t.PRECONDITION_NOT_MET
        }
        // The callback runs on as OpenRTM's context thread runs it; the call waits for the new state only
        // transition_timeout long (ExecutionContextBase.waitForActivated and the like), then answers RTC_ERROR.
        val made = CompletableFuture<ReturnCode_t>()
        thread(isDaemon = true, name = "${component.instanceName} slow transition") {
            Thread.sleep(runtime.onHost(callbackTime).inWholeMilliseconds)
            made.complete(transition(component, from, to, action))
        }
        return try {
            made.get(runtime.onHost(transitionTimeout).inWholeNanoseconds, TimeUnit.NANOSECONDS)
        } catch (e: TimeoutException) {
            ReturnCode_t.RTC_ERROR
        }
    }

    private fun transition(
        component: RuntimeComponent,
        from: LifeCycleState,
        to: LifeCycleState,
        action: Behaviour.(ComponentContext) -> Boolean,
    ): ReturnCode_t {
        val code =
            synchronized(lock) {
                val participant = participants[component] ?: return ReturnCode_t.BAD_PARAMETER
                if (participant.state != from) return ReturnCode_t.PRECONDITION_NOT_MET
                // The thread that would make the transition is stuck: the request waits for it in vain.
                if (stuckIn != null) return@synchronized null
                // OpenRTM's on_activated updates the configuration before the component's onActivated.
                if (to == LifeCycleState.ACTIVE_STATE) component.updateConfiguration()
                val succeeded = component.perform(participant.handle, action)
                when {
                    to == LifeCycleState.INACTIVE_STATE && from == LifeCycleState.ACTIVE_STATE -> {
                        enter(participant, to, announced = succeeded)
                        return@synchronized ReturnCode_t.RTC_OK
                    }
                    succeeded -> enter(participant, to)
                    from == LifeCycleState.ERROR_STATE -> Unit
                    else -> enter(participant, LifeCycleState.ERROR_STATE)
                }
                if (succeeded) ReturnCode_t.RTC_OK else ReturnCode_t.RTC_ERROR
            }
        return code
            ?: ReturnCode_t.RTC_ERROR.also { Thread.sleep(runtime.onHost(transitionTimeout).inWholeMilliseconds) }
    }

    /**
     * Moves [participant] to [state], announcing it unless the callback that made the move failed ([announced] false:
     * OpenRTM's observer tells only of callbacks that succeeded), and only then updating the state, as OpenRTM's state
     * machine does once the actions are done.
     */
    private fun enter(participant: Participant, state: LifeCycleState, announced: Boolean = true) {
        val before = participant.state
        participant.component.record(StateTransition(participant.handle, before, state, System.nanoTime()))
        val hub = participant.component.observers
        if (announced) {
            when (state) {
                LifeCycleState.ACTIVE_STATE -> hub.raise(StatusKind.RTC_STATUS, "ACTIVE:${participant.handle}")
                LifeCycleState.INACTIVE_STATE -> hub.raise(StatusKind.RTC_STATUS, "INACTIVE:${participant.handle}")
                LifeCycleState.ERROR_STATE -> hub.raise(StatusKind.RTC_STATUS, "ERROR:${participant.handle}")
                else -> Unit
            }
        }
        participant.state = state
    }

    /**
     * Aborts ACTIVE [participant], as OpenRTM's state machine leaves ACTIVE for ERROR: the exit action runs
     * `on_deactivated` (INACTIVE is announced if it succeeds), the entry action `on_aborting` (ERROR).
     */
    private fun abort(participant: Participant) {
        val component = participant.component
        if (component.perform(participant.handle) { rtc -> onDeactivated(rtc) }) {
            component.observers.raise(StatusKind.RTC_STATUS, "INACTIVE:${participant.handle}")
        }
        enter(participant, LifeCycleState.ERROR_STATE)
    }

    private fun tick() {
        synchronized(lock) {
            periods++
            // The stuck execution returns once the hang ends; until then the thread does nothing else.
            stuckIn?.let { if (it.isExecutionHung) return else stuckIn = null }
            for (participant in participants.values) {
                val component = participant.component
                if (participant.state == LifeCycleState.ACTIVE_STATE && component.isExecutionHung) {
                    stuckIn = component
                    return
                }
                when (participant.state) {
                    // on_state_update follows a successful on_execute; on_error runs each period in ERROR: both update
                    // the configuration.
                    LifeCycleState.ACTIVE_STATE ->
                        if (component.execute(participant.handle)) component.updateConfiguration()
                        else abort(participant)
                    LifeCycleState.ERROR_STATE -> component.updateConfiguration()
                    else -> Unit
                }
            }
        }
    }

    private fun schedule() {
        val period = runtime.onHost((1 / rate).seconds).inWholeNanoseconds.coerceAtLeast(1)
        ticker = runtime.scheduler.scheduleAtFixedRate(::tick, period, period, TimeUnit.NANOSECONDS)
    }

    private fun announce(hint: (Participant) -> String) {
        participants.values.forEach { it.component.observers.raise(StatusKind.EC_STATUS, hint(it)) }
    }
}
