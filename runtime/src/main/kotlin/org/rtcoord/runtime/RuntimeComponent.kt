package org.rtcoord.runtime

import OpenRTM.DataFlowComponentHelper
import OpenRTM.DataFlowComponentPOA
import RTC.ComponentProfile
import RTC.ExecutionContext
import RTC.ExtendedFsmService
import RTC.ExtendedFsmServiceHelper
import RTC.LifeCycleState
import RTC.PortService
import RTC.ReturnCode_t
import _SDOPackage.Configuration
import _SDOPackage.ConfigurationHelper
import _SDOPackage.DeviceProfile
import _SDOPackage.InterfaceNotImplemented
import _SDOPackage.InvalidParameter
import _SDOPackage.Monitoring
import _SDOPackage.NameValue
import _SDOPackage.Organization
import _SDOPackage.SDOService
import _SDOPackage.ServiceProfile
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlinx.coroutines.CoroutineScope
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.rtcoord.idl.ObjectIdentity
import org.slf4j.LoggerFactory

/**
 * An RT Component implementing `OpenRTM::DataFlowComponent` as OpenRTM-aist components do: profile, ports, the
 * execution contexts its type says it owns (handles 0, 1, ...) plus participating ones (handles from 1000),
 * configuration sets and ComponentObserver support, running its type's [Behaviour].
 *
 * Tests drive faults through it: [fail] (or parameter `fail=1`) makes the next execution fail into ERROR and a reset
 * recovers it; [breakDown] makes it fail and keeps its `on_reset` failing until [repair], as a component whose hardware
 * stays broken; [hang] makes every call to the component's objects block until [release]; [hangExecution] makes its
 * `on_execute` stop returning, which stalls its execution contexts, until [resumeExecution]; [freezeOutput] keeps it
 * ACTIVE and executing but publishing nothing, until [thawOutput].
 *
 * It is longer than most files here because one servant answers every operation of the interfaces a DataFlowComponent
 * inherits (LightweightRTObject, RTObject, SDO, DataFlowComponentAction); ports, contexts, configuration and the
 * observer live in classes of their own.
 */
public class RuntimeComponent
internal constructor(
    public val type: ComponentType,
    public val instanceName: String,
    private val runtime: RuntimeProcess,
    /** The naming contexts it is bound under. */
    public val contexts: List<String>,
) : DataFlowComponentPOA() {
    private val log = LoggerFactory.getLogger(RuntimeComponent::class.java)
    private val lock = Any()
    private val behaviour = type.behaviour()
    private val participating = sortedMapOf<Int, RuntimeExecutionContext>()
    private val context = BehaviourContext()

    private val transitionLog = java.util.concurrent.ConcurrentLinkedQueue<StateTransition>()

    @Volatile private var injectedFailure = false
    @Volatile private var broken = false
    @Volatile private var executionHung = false
    @Volatile private var outputFrozen = false
    @Volatile private var exited = false
    @Volatile private var callbackTime = Duration.ZERO
    private val calls = ConcurrentHashMap<String, AtomicInteger>()

    internal val orb: RuntimeOrb
        get() = runtime.orb

    internal val scope: CoroutineScope
        get() = runtime.scope

    internal val gate = Gate()
    internal val observers =
        ObserverHub(instanceName, type.observerFlavours, runtime.scope, runtime::onHost) { gate.isClosed }
    private val configuration = RuntimeConfiguration(runtime.orb.orb, type, observers, gate)
    private val fsm = type.fsm?.let { spec -> RuntimeFsm(spec, observers::raiseFsm, ::nameValue) }
    private var fsmRef: ExtendedFsmService? = null
    private val ports = type.ports.map { RuntimePort(it, this) }
    private val ownedContexts = type.contexts.map { RuntimeExecutionContext(runtime, this, it) }

    /** The first owned context, handle 0: the one tools act in by default. */
    private val owned = ownedContexts.first()

    /** This component's object reference. */
    public lateinit var ref: OpenRTM.DataFlowComponent
        private set

    /** The reference's [ObjectIdentity], to compare references callers pass in cheaply. */
    internal val identity: String by lazy { ObjectIdentity.of(ref) }

    private lateinit var configurationRef: Configuration

    internal fun start() {
        ref = DataFlowComponentHelper.narrow(orb.activate(this))
        configurationRef = ConfigurationHelper.narrow(orb.activate(configuration))
        fsmRef = fsm?.let { ExtendedFsmServiceHelper.narrow(orb.activate(it)) }
        ports.forEach { it.activate(orb) }
        ownedContexts.forEachIndexed { handle, context ->
            context.activate(orb)
            context.join(this, handle)
            context.start()
        }
    }

    /** The lifecycle state in the first owned execution context. */
    public val state: LifeCycleState
        get() = owned.stateOf(this)

    /** Whether the component has exited. */
    public val isExited: Boolean
        get() = exited

    /** Activates the component in its first owned execution context, as `rtact` does. */
    public fun activate(): ReturnCode_t = owned.activate_component(ref)

    /**
     * Activates the component in each execution context it owns, in handle order; the first answer that is not
     * `RTC_OK`, else `RTC_OK`.
     */
    public fun activateEverywhere(): ReturnCode_t =
        ownedContexts.map { it.activate_component(ref) }.firstOrNull { it != ReturnCode_t.RTC_OK }
            ?: ReturnCode_t.RTC_OK

    /** Deactivates the component in its first owned execution context, as `rtdeact` does. */
    public fun deactivate(): ReturnCode_t = owned.deactivate_component(ref)

    /** Resets the component in its first owned execution context, as `rtreset` does. */
    public fun reset(): ReturnCode_t = owned.reset_component(ref)

    /**
     * Logs [message] at [level] (`WARN`, `ERROR`, ...) to where its process sends log records
     * ([RuntimeProcess.sendLogsTo]), as its logger named by its instance name; returns whether it was sent.
     */
    public fun log(level: String, message: String): Boolean =
        runtime.logSender?.send(instanceName, level, message) ?: false

    /** Makes the next execution fail, sending the component to ERROR; a reset clears it. */
    public fun fail() {
        injectedFailure = true
    }

    /**
     * Breaks the component until [repair]: its executions fail, sending it to ERROR, and its `on_reset` fails while the
     * fault holds, so `reset_component` answers `RTC_ERROR` and it stays in ERROR.
     */
    public fun breakDown() {
        broken = true
    }

    /** Ends the fault [breakDown] began: the next reset succeeds. */
    public fun repair() {
        broken = false
    }

    /** Whether a fault from [breakDown] holds. */
    public val isBroken: Boolean
        get() = broken

    /**
     * Makes the component's `on_execute` stop returning until [resumeExecution], as a callback stuck on a device does:
     * every execution context running it stalls with it (see [RuntimeExecutionContext]), while its objects still answer
     * and its observers still get heartbeats.
     */
    public fun hangExecution() {
        executionHung = true
    }

    /** Lets the hung `on_execute` return: its contexts run again. */
    public fun resumeExecution() {
        executionHung = false
    }

    /**
     * Freezes the component's output until [thawOutput]: it stays ACTIVE and executes, but its out-ports publish
     * nothing, as a sensor whose driver stopped delivering while its component runs on.
     */
    public fun freezeOutput() {
        outputFrozen = true
    }

    /** Ends [freezeOutput]: its out-ports publish again. */
    public fun thawOutput() {
        outputFrozen = false
    }

    /** Whether its output is frozen ([freezeOutput]). */
    public val isOutputFrozen: Boolean
        get() = outputFrozen

    /**
     * Loses every connector of the component's ports, as an out-port whose write meets `CONNECTION_LOST` (its peer
     * unreachable) disconnects that connector: each port of each connector drops it and tells its observers. The
     * component runs on, unconnected.
     */
    public fun loseConnectors() {
        ports.forEach { it.disconnect_all() }
    }

    /**
     * Makes the component's `on_activated`, `on_deactivated` and `on_reset` each take [duration] (zero: none), as
     * callbacks that open or close a slow device do. Longer than its context's transition timeout (0.5 s), the context
     * answers `RTC_ERROR` while the callback still runs, and the new state shows when it returns (see
     * [RuntimeExecutionContext]).
     */
    public fun slowTransitions(duration: Duration) {
        require(!duration.isNegative()) { "a callback cannot take $duration" }
        callbackTime = duration
    }

    /** How long each transition callback takes ([slowTransitions]). */
    internal val transitionCallbackTime: Duration
        get() = callbackTime

    /** The state its FSM is in (a leaf state), or null for a component without one ([ComponentType.fsm]). */
    public val fsmState: String?
        get() = fsm?.state

    /**
     * Hands its FSM [event] as its event port would, the nearest state that handles it changing the state; returns the
     * state it leads to. An event no state handles there is refused.
     */
    public fun fsmEvent(event: String): String =
        (fsm ?: throw IllegalStateException("$instanceName has no FSM")).dispatch(event)

    /** Whether the component's execution hangs ([hangExecution]). */
    public val isExecutionHung: Boolean
        get() = executionHung

    /** Whether an owned context's thread is stuck in a hung execution (once it reached it). */
    public val isContextStuck: Boolean
        get() = ownedContexts.any { it.isStuck }

    /**
     * How many periods its first owned context has run so far: a test that shows what the component does not do in some
     * periods waits for them to pass instead of sleeping.
     */
    public val periods: Long
        get() = owned.periods

    /** Makes every call to this component's objects block until [release]; heartbeats stop too. */
    public fun hang(): Unit = gate.close()

    /** Lets held and later calls through again. */
    public fun release(): Unit = gate.open()

    /** How many calls [hang] holds now: what a test waits for to know its call reached the hung component. */
    public val heldCalls: Int
        get() = gate.held

    /**
     * The value of parameter [name] as the component uses it: its bound variable, which takes the active configuration
     * set's value only when the component next runs (activation, execution, ERROR).
     */
    public fun parameter(name: String): String = configuration.parameter(name)

    /** The id of the active configuration set; null while none is (after a set was written, added or removed). */
    public val activeConfigurationSet: String?
        get() = configuration.activeSet

    /** The latest sample in-port [port] received. */
    public fun latest(port: String): Sample? = port(port).latest()

    /** Every lifecycle transition the component made, in order. */
    public val transitions: List<StateTransition>
        get() = transitionLog.toList()

    /** The ids of the observers attached to this component. */
    public val observerIds: Set<String>
        get() = observers.ids

    /** The references of the observers attached to this component: where it calls them back. */
    public val observerReferences: List<org.omg.CORBA.Object>
        get() = observers.references

    /**
     * How many heartbeats it sent its observers so far: a test showing what a watcher does not do between beats waits
     * for beats to pass instead of sleeping.
     */
    public val heartbeats: Long
        get() = observers.heartbeats

    /** How many times [operation] (`get_component_profile`, ...) was called on the component itself so far. */
    public fun calls(operation: String): Int = calls[operation]?.get() ?: 0

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream {
        calls.computeIfAbsent(method) { AtomicInteger() }.incrementAndGet()
        gate.pass()
        return super._invoke(method, input, handler)
    }

    internal fun perform(handle: Int, action: Behaviour.(ComponentContext) -> Boolean): Boolean =
        synchronized(lock) {
            try {
                behaviour.action(context)
            } catch (e: Exception) {
                log.info("{}: behaviour failed in context {}: {}", instanceName, handle, e.toString())
                false
            }
        }

    internal fun execute(handle: Int): Boolean {
        // Every period: a component without the parameter must not pay for an exception each time.
        if (injectedFailure || broken || configuration.parameterOrNull("fail") == "1") return false
        context.tick++
        return perform(handle) { onExecute(it) }
    }

    /** Brings a newly activated set's values to the variables, as OpenRTM does when a component runs. */
    internal fun updateConfiguration(): Unit = configuration.update()

    internal fun attach(context: RuntimeExecutionContext): Int =
        synchronized(lock) {
            val handle = generateSequence(1000) { it + 1 }.first { it !in participating }
            participating[handle] = context
            handle
        }

    internal fun detach(handle: Int) = synchronized(lock) { participating.remove(handle) }

    internal fun nameValue(name: String, value: String): NameValue =
        NameValue(name, orb.orb.create_any().apply { insert_string(value) })

    private fun port(name: String): RuntimePort =
        ports.firstOrNull { it.spec.name == name }
            ?: throw IllegalArgumentException("$instanceName has no port '$name'")

    private fun contextOf(handle: Int): RuntimeExecutionContext? =
        ownedContexts.getOrNull(handle) ?: synchronized(lock) { participating[handle] }

    private fun handleOf(ec: ExecutionContext?): Int {
        if (ec == null) return -1
        ownedContexts
            .indexOfFirst { ec._is_equivalent(it.ref) }
            .takeIf { it >= 0 }
            ?.let {
                return it
            }
        return synchronized(lock) { participating.entries.firstOrNull { ec._is_equivalent(it.value.ref) }?.key } ?: -1
    }

    override fun get_component_profile(): ComponentProfile =
        ComponentProfile(
            instanceName,
            type.typeName,
            type.description,
            type.version,
            type.vendor,
            type.category,
            ports.map { it.get_port_profile() }.toTypedArray(),
            null,
            profileProperties().map { (name, value) -> nameValue(name, value) }.toTypedArray(),
        )

    private fun profileProperties(): Map<String, String> =
        linkedMapOf(
            "implementation_id" to type.typeName,
            "type_name" to type.typeName,
            "description" to type.description,
            "version" to type.version,
            "vendor" to type.vendor,
            "category" to type.category,
            "activity_type" to "PERIODIC",
            "max_instance" to "0",
            "language" to "Kotlin",
            "lang_type" to "compile",
            "instance_name" to instanceName,
            "exec_cxt.periodic.type" to owned.typeName,
            "exec_cxt.periodic.rate" to type.rate.toString(),
            "naming.names" to "$instanceName.rtc",
            "sdo.service.consumer.available_services" to type.observerFlavours.joinToString(",") { it.repositoryId },
        ) +
            fsmProperties() +
            runtime.managerName?.let { mapOf("manager.instance_name" to it) }.orEmpty() +
            type.parameters.associate { "conf.default.${it.name}" to it.default }

    /** An FSM component lists the service as OpenRTM-aist's `SdoServiceAdmin` lists the providers it loaded. */
    private fun fsmProperties(): Map<String, String> =
        if (fsm == null) emptyMap()
        else mapOf("sdo.service.provider.available_services" to ExtendedFsmServiceHelper.id())

    override fun get_ports(): Array<PortService> = ports.map { it.ref }.toTypedArray()

    override fun initialize(): ReturnCode_t = ReturnCode_t.PRECONDITION_NOT_MET

    override fun _finalize(): ReturnCode_t = ReturnCode_t.PRECONDITION_NOT_MET

    /**
     * As `RTObject.exit`: the component finalises and its objects are deactivated before the reply, so any later call
     * on them raises `OBJECT_NOT_EXIST`; its manager unregisters it and unbinds its name later, at its next clean-up
     * ([RuntimeProcess.cleanupDelay]). Exiting again answers `RTC_OK`.
     */
    override fun exit(): ReturnCode_t {
        if (exited) return ReturnCode_t.RTC_OK
        exited = true
        observers.raise(StatusKind.RTC_STATUS, "FINALIZE:0")
        observers.raise(StatusKind.EC_STATUS, "SHUTDOWN:0")
        runtime.finalized(this)
        return ReturnCode_t.RTC_OK
    }

    /** Leaves every execution context and deactivates all objects; called once, by the runtime. */
    internal fun teardown() {
        ownedContexts.forEach {
            it.shutdown()
            it.leave(this)
        }
        synchronized(lock) { participating.values.toList() }.forEach { it.leave(this) }
        ports.forEach {
            it.disconnect_all()
            it.deactivate(orb)
        }
        observers.close()
        (listOf(configuration) + ownedContexts + this).forEach(orb::deactivate)
    }

    override fun is_alive(ec: ExecutionContext?): Boolean = !exited && handleOf(ec) >= 0

    override fun get_context(handle: Int): ExecutionContext? = contextOf(handle)?.ref

    override fun get_owned_contexts(): Array<ExecutionContext> = ownedContexts.map { it.ref }.toTypedArray()

    override fun get_participating_contexts(): Array<ExecutionContext> =
        synchronized(lock) { participating.values.map { it.ref }.toTypedArray() }

    override fun get_context_handle(ec: ExecutionContext?): Int = handleOf(ec)

    override fun attach_context(ec: ExecutionContext?): Int {
        val context = runtime.executionContextOf(ec) ?: return -1
        return attach(context)
    }

    override fun detach_context(handle: Int): ReturnCode_t =
        if (handle >= 1000 && detach(handle) != null) ReturnCode_t.RTC_OK else ReturnCode_t.BAD_PARAMETER

    override fun on_initialize(): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_finalize(): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_startup(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_shutdown(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_activated(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_deactivated(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_aborting(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_error(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_reset(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_execute(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_state_update(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun on_rate_changed(ec: Int): ReturnCode_t = ReturnCode_t.RTC_OK

    override fun get_sdo_id(): String = instanceName

    override fun get_sdo_type(): String = type.typeName

    override fun get_device_profile(): DeviceProfile =
        DeviceProfile("", type.vendor, type.typeName, type.version, emptyArray())

    /**
     * The attached observers' profiles, as OpenRTM-aist 1.0 lists added services (later versions list only the services
     * a component provides): a coordinator restarted can find the observers its previous run left behind, and a test
     * can reach an observer as any client could.
     */
    override fun get_service_profiles(): Array<ServiceProfile> = observers.profiles.toTypedArray()

    override fun get_service_profile(id: String): ServiceProfile =
        observers.profiles.firstOrNull { it.id == id } ?: throw InvalidParameter("no service '$id'")

    // What rtctree's get_extended_fsm_service asks for; OpenRTM-aist finds providers by their interface's id.
    override fun get_sdo_service(id: String): SDOService =
        fsmRef?.takeIf { id == ExtendedFsmServiceHelper.id() } ?: throw InvalidParameter("no service '$id'")

    override fun get_configuration(): Configuration = configurationRef

    override fun get_monitoring(): Monitoring = throw InterfaceNotImplemented("monitoring is not implemented")

    override fun get_organizations(): Array<Organization> = emptyArray()

    override fun get_owned_organizations(): Array<Organization> = emptyArray()

    override fun get_status_list(): Array<NameValue> = emptyArray()

    override fun get_status(name: String): org.omg.CORBA.Any = throw InvalidParameter("no status '$name'")

    private inner class BehaviourContext : ComponentContext {
        override val instanceName: String
            get() = this@RuntimeComponent.instanceName

        override var tick: Long = 0

        override fun parameter(name: String): String = configuration.parameter(name)

        override fun write(port: String, value: Any) = port(port).write(value)

        override fun latest(port: String): Sample? = port(port).latest()
    }

    internal fun ownedContextIf(ec: ExecutionContext): RuntimeExecutionContext? = ownedContexts.firstOrNull {
        ec._is_equivalent(it.ref)
    }

    internal fun record(transition: StateTransition) {
        transitionLog += transition
    }

    /** A reset clears an injected failure: the fault is over. */
    internal fun clearFailure() {
        injectedFailure = false
    }
}
