package org.rtcoord.runtime

import RTC.ExecutionContext
import RTC.LightweightRTObject
import java.net.InetAddress
import java.net.InetSocketAddress
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.Executors
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.omg.CosNaming.NamingContextExt
import org.omg.CosNaming.NamingContextExtHelper
import org.omg.CosNaming.NamingContextPackage.AlreadyBound
import org.omg.CosNaming.NamingContextPackage.NotFound
import org.rtcoord.idl.ObjectIdentity
import org.rtcoord.idl.OrbRecipe
import org.slf4j.LoggerFactory

/**
 * One "process", like an OpenRTM-aist executable: an ORB, the components it hosts, their execution contexts' scheduler,
 * and their registration in a naming service under [contexts] (`<host>.host_cxt` by default).
 */
public class RuntimeProcess
private constructor(
    public val orb: RuntimeOrb,
    namingAddress: String?,
    public val contexts: List<String>,
    /**
     * The instance name of the manager this process stands for, which OpenRTM-aist's manager passes on to each
     * component it creates (`manager.instance_name` in its profile); null: its components' profiles do not say.
     */
    public val managerName: String?,
    /**
     * How many times as fast as the robot's clock the process runs: its execution contexts tick, its observers beat and
     * its clean-ups come that much sooner, while every rate and interval it reports or is given stays the robot's. A
     * tree at the same speed (`TreeConfig.speed`) sees the robot's system, faster. 1 by default.
     */
    public val speed: Double,
) : AutoCloseable {
    private val log = LoggerFactory.getLogger(RuntimeProcess::class.java)
    private val hosted = CopyOnWriteArrayList<RuntimeComponent>()
    private val naming: NamingContextExt? = namingAddress?.let {
        NamingContextExtHelper.narrow(orb.orb.string_to_object(it))
    }

    /**
     * The thread that ticks every execution context of the process. One: with two, the idle one woke at every tick to
     * take over the queue's wait (a scheduled pool's leader and follower), doubling the process's wake-ups.
     */
    internal val scheduler: ScheduledExecutorService = Executors.newSingleThreadScheduledExecutor { task ->
        Thread(task, "runtime-ec-${threads.incrementAndGet()}").apply { isDaemon = true }
    }
    internal val scope =
        CoroutineScope(SupervisorJob() + Dispatchers.IO.limitedParallelism(16) + CoroutineName("runtime-process"))

    /** The components this runtime hosts, in creation order. */
    public val components: List<RuntimeComponent>
        get() = ArrayList(hosted)

    /**
     * Creates and starts an instance of [type] named [instanceName] (by default the type name plus the lowest free
     * index, as OpenRTM names them), and binds it in the naming service when [bind] is set (see [register]).
     */
    public fun create(
        type: ComponentType,
        instanceName: String = nextName(type.typeName),
        bind: Boolean = true,
        contexts: List<String> = this.contexts,
    ): RuntimeComponent {
        require(hosted.none { it.instanceName == instanceName }) { "a component named $instanceName exists" }
        val component = RuntimeComponent(type, instanceName, this, contexts)
        component.start()
        hosted += component
        if (bind) register(component)
        return component
    }

    /**
     * Binds [component]'s name. A name server that does not answer fails neither the creation nor the manager that
     * asked for it: OpenRTM-aist's naming manager catches what binding throws, and its naming update (every
     * `naming.update.interval`) binds the name once the server answers again.
     */
    private fun register(component: RuntimeComponent) {
        val name = "${component.instanceName}.rtc"
        try {
            bind(name, component.ref, component.contexts)
        } catch (e: org.omg.CORBA.SystemException) {
            log.warn("{}: the name server does not answer ({}): bound at the next naming update", name, e.toString())
            scope.launch {
                do delay(onHost(NAMING_UPDATE)) while (
                    component in hosted && runCatching { bind(name, component.ref, component.contexts) }.isFailure
                )
            }
        }
    }

    /** The hosted component named [instanceName]. */
    public fun component(instanceName: String): RuntimeComponent =
        hosted.firstOrNull { it.instanceName == instanceName }
            ?: throw IllegalArgumentException("no component $instanceName")

    /** The name OpenRTM would give the next instance of [typeName]: `typeName` plus the lowest free index. */
    public fun nextName(typeName: String): String =
        generateSequence(0) { it + 1 }.map { "$typeName$it" }.first { name -> hosted.none { it.instanceName == name } }

    /** Binds (or rebinds) [name] to [target] under this runtime's contexts, creating them as needed. */
    public fun bind(name: String, target: org.omg.CORBA.Object, contexts: List<String> = this.contexts) {
        val root = naming ?: return
        var context: org.omg.CosNaming.NamingContext = root
        for (segment in contexts) {
            val path = root.to_name(segment)
            context =
                try {
                    context.bind_new_context(path)
                } catch (e: AlreadyBound) {
                    org.omg.CosNaming.NamingContextHelper.narrow(context.resolve(path))
                }
        }
        context.rebind(root.to_name(name), target)
    }

    /** Binds every hosted component again, as OpenRTM's periodic naming update does after a name server restart. */
    public fun rebindAll() {
        hosted.forEach { bind("${it.instanceName}.rtc", it.ref, it.contexts) }
    }

    internal fun unbind(name: String, contexts: List<String>) {
        val root = naming ?: return
        try {
            root.unbind(root.to_name((contexts + name).joinToString("/")))
        } catch (e: NotFound) {
            log.debug("{} was not bound", name)
        } catch (e: org.omg.CORBA.SystemException) {
            log.debug("could not unbind {}: {}", name, e.toString())
        }
    }

    /**
     * How long after a component exits its manager unregisters it and unbinds its name, as OpenRTM-aist's periodic
     * `Manager.cleanupComponents` does (every second in OpenRTM-aist-Python; about 0.3 s was observed). Meanwhile its
     * name resolves to a dead object and its manager still lists it.
     */
    @Volatile public var cleanupDelay: Duration = 300.milliseconds

    /** How long [robotTime] lasts on this host's clock, at [speed]. */
    internal fun onHost(robotTime: Duration): Duration = if (speed == 1.0) robotTime else robotTime / speed

    /** An exiting component finalised: its objects go now, its registration at the next clean-up. */
    internal fun finalized(component: RuntimeComponent) {
        component.teardown()
        // Off the contexts' thread: unbinding waits on the naming service, which may be down.
        scope.launch {
            delay(onHost(cleanupDelay))
            cleanUp(component)
        }
    }

    /** Unregisters an exited component and unbinds its name. */
    private fun cleanUp(component: RuntimeComponent) {
        if (!hosted.remove(component)) return
        unbind("${component.instanceName}.rtc", component.contexts)
    }

    /** Removes a component at once: unbinds it, stops its contexts and deactivates its objects. */
    private fun dispose(component: RuntimeComponent) {
        val exited = component.isExited
        cleanUp(component)
        if (!exited) component.teardown()
    }

    internal fun componentOf(ref: LightweightRTObject?): RuntimeComponent? =
        ref?.let(ObjectIdentity::of)?.let { target ->
            everywhere().flatMap { it.hosted }.firstOrNull { it.identity == target }
        }

    internal fun executionContextOf(ref: ExecutionContext?): RuntimeExecutionContext? = ref?.let { target ->
        everywhere().flatMap { it.hosted }.firstNotNullOfOrNull { it.ownedContextIf(target) }
    }

    /** Exits every component and stops the ORB. */
    /** Where its components' log records go, as OpenRTM-aist's logger plugins send them; null: nowhere. */
    @Volatile
    internal var logSender: FluentLogSender? = null
        private set

    /**
     * Sends its components' log records ([RuntimeComponent.log]) to the Fluentd forward input at [address] as the
     * process of manager [manager] (its `manager.instance_name`), as an `rtc.conf` naming a fluentd log stream makes
     * OpenRTM-aist's do.
     */
    public fun sendLogsTo(address: InetSocketAddress, manager: String) {
        logSender?.close()
        logSender = FluentLogSender(address, manager)
    }

    override fun close() {
        if (!runtimes.remove(this)) return
        logSender?.close()
        hosted.forEach { it.gate.end() }
        ArrayList(hosted).forEach(::dispose)
        scheduler.shutdownNow()
        scope.cancel()
        orb.close()
    }

    @Volatile private var killed = false

    /** Whether [kill] ended it. */
    public val isKilled: Boolean
        get() = killed

    /**
     * Ends the process as `kill -9` ends an OpenRTM-aist executable: its ORB stops answering at once, its components
     * stop executing and tell nobody, and every name it bound stays bound (a dead reference), since only a clean
     * shutdown unbinds (`Manager.shutdownNaming`). Closing it later changes nothing.
     */
    public fun kill() {
        if (!runtimes.remove(this)) return
        killed = true
        hosted.forEach { it.gate.end() }
        scheduler.shutdownNow()
        scope.cancel()
        orb.close()
    }

    private fun everywhere(): List<RuntimeProcess> = listOf(this) + runtimes.filter { it !== this }

    public companion object {
        private val threads = AtomicInteger()

        /** OpenRTM-aist's default `naming.update.interval`. */
        private val NAMING_UPDATE = 10.seconds
        private val runtimes = CopyOnWriteArrayList<RuntimeProcess>()

        /** The context OpenRTM binds components in by default: `<hostname>.host_cxt`. */
        public val hostContext: String =
            "${runCatching { InetAddress.getLocalHost().hostName }.getOrDefault("localhost")}.host_cxt"

        /**
         * Starts a runtime whose ORB listens on [host]:[port] (0: any free port) and registers its components with the
         * naming service at [naming] (a `corbaloc:` address; null: none); its components' profiles name [managerName]
         * as their manager's when it is set. It runs [speed] times as fast as the robot's clock. Its ORB keeps
         * [idleRequestThreads] request threads when idle ([RuntimeOrb.start]).
         */
        public fun start(
            naming: String?,
            contexts: List<String> = listOf(hostContext),
            port: Int = 0,
            host: String = "127.0.0.1",
            managerName: String? = null,
            speed: Double = 1.0,
            idleRequestThreads: Int = OrbRecipe.REQUEST_THREADS,
        ): RuntimeProcess {
            require(speed > 0 && speed.isFinite()) { "speed must be positive, was $speed" }
            val orb = RuntimeOrb.start(port, host, idleRequestThreads = idleRequestThreads)
            return RuntimeProcess(orb, naming, contexts, managerName, speed).also {
                runtimes += it
            }
        }
    }
}
