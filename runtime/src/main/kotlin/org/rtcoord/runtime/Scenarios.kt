package org.rtcoord.runtime

/** Ready-made systems for tests, demos and benchmarks. */
public object Scenarios {
    private val fail = ParameterSpec.integer("fail", 0)

    /** A laser scanner: out-port `laser` (TimedDoubleSeq). */
    public val laser: ComponentType =
        ComponentType(
            "laser",
            listOf(PortSpec.DataOut("laser", DataType.TIMED_DOUBLE_SEQ)),
            listOf(fail),
            behaviour = { Behaviour.source("laser") { tick -> DoubleArray(8) { 4.0 + (tick + it) % 3 } } },
        )

    /** A gyro: out-port `gyro` (TimedDouble). */
    public val gyro: ComponentType =
        ComponentType(
            "gyro",
            listOf(PortSpec.DataOut("gyro", DataType.TIMED_DOUBLE)),
            listOf(fail),
            behaviour = { Behaviour.source("gyro") { tick -> 0.01 * (tick % 100) } },
        )

    /** Wheel odometry: out-port `odo` (TimedDoubleSeq: x, y, heading). */
    public val odometry: ComponentType =
        ComponentType(
            "odometry",
            listOf(PortSpec.DataOut("odo", DataType.TIMED_DOUBLE_SEQ)),
            listOf(fail),
            behaviour = { Behaviour.source("odo") { tick -> doubleArrayOf(0.1 * tick, 0.0, 0.0) } },
        )

    /** The laser-based localiser: in-ports `laser`, `odo`, out-port `pose`; parameter `gain`. */
    public val laserLocalise: ComponentType = localiser("laser_localise", "laser", "odo")

    /** The fallback localiser from odometry and gyro: in-ports `odo`, `gyro`, out-port `pose`. */
    public val odoLocalise: ComponentType = localiser("odo_localise", "odo", "gyro")

    private fun localiser(typeName: String, first: String, second: String): ComponentType {
        val inputs = listOf(first, second)
        return ComponentType(
            typeName,
            listOf(
                PortSpec.DataIn(first, if (first == "gyro") DataType.TIMED_DOUBLE else DataType.TIMED_DOUBLE_SEQ),
                PortSpec.DataIn(second, if (second == "gyro") DataType.TIMED_DOUBLE else DataType.TIMED_DOUBLE_SEQ),
                PortSpec.DataOut("pose", DataType.TIMED_DOUBLE_SEQ),
            ),
            listOf(fail, ParameterSpec.decimal("gain", 1.0)),
            configurationSets =
                mapOf(
                    "precise" to mapOf("fail" to "0", "gain" to "0.5"),
                    "__constraints__" to mapOf("gain" to "0<x<10"),
                ),
            behaviour = { Behaviour.fuse(inputs, "pose", ::poseFromOdometry) },
        )
    }

    /** The pose a localiser reports: the odometry's (x, y, heading), or the origin until it has one. */
    private fun poseFromOdometry(samples: List<Sample?>): DoubleArray =
        samples.firstNotNullOfOrNull { (it?.value as? DoubleArray)?.takeIf { pose -> pose.size == 3 } }
            ?: DoubleArray(3)

    /**
     * A map server with one service port, `map`: it provides the interface `map` (`MapServer::Map`) and requires `pose`
     * (`Localisation::PoseSource`), registered in that order as a component's `registerProvider` and `registerConsumer`
     * calls would.
     */
    public val mapServer: ComponentType =
        ComponentType(
            "map_server",
            listOf(
                PortSpec.Service(
                    "map",
                    provided = mapOf("map" to "MapServer::Map"),
                    required = mapOf("pose" to "Localisation::PoseSource"),
                )
            ),
        )

    /**
     * The modules the localisation system's manager can load: `sensors.so`, `localisers.so` (the laser localiser) and
     * `odo_localise.so` (the fallback localiser).
     */
    public val localisationModules: List<RuntimeModule> =
        listOf(
            RuntimeModule("sensors.so", listOf(laser, gyro, odometry)),
            RuntimeModule("localisers.so", listOf(laserLocalise)),
            RuntimeModule("odo_localise.so", listOf(odoLocalise)),
        )

    /**
     * The paper's localisation system: `laser0`, `gyro0`, `odometry0` and `laser_localise0` (fed by the laser and
     * odometry), hosted by a slave manager that loaded `sensors.so` and `localisers.so`, connected and active;
     * `odo_localise` can be created through the master `manager.mgr`, its module loadable but not loaded at start, and
     * is not running. Its ORBs listen on [host].
     */
    public fun localisation(naming: String, host: String = "127.0.0.1"): RtSystem =
        rtSystem(naming, host) {
            manager(*localisationModules.toTypedArray(), preload = listOf("sensors.so", "localisers.so"))
            component(laser)
            component(gyro)
            component(odometry)
            component(laserLocalise)
            connect("laser0:laser", "laser_localise0:laser")
            connect("odometry0:odo", "laser_localise0:odo")
            activate("laser0", "gyro0", "odometry0", "laser_localise0")
        }

    /**
     * OpenRTM-aist's ConfigSample example with its `configsample.conf` (OpenRTM-aist-Python
     * `OpenRTM_aist/examples/ConfigSample`): seven parameters, the sets `default`, `mode0` and `mode1`, and the hidden
     * `__widget__` and `__constraints__`. Its sets hold values outside their own constraints (`mode0`'s `int_param0` is
     * 12345 where `__constraints__` says `0<=x<=150`): OpenRTM-aist never checks them.
     */
    public val configSample: ComponentType =
        ComponentType(
            "ConfigSample",
            parameters =
                listOf(
                    ParameterSpec.integer("int_param0", 0),
                    ParameterSpec.integer("int_param1", 1),
                    ParameterSpec.decimal("double_param0", 0.99),
                    ParameterSpec.decimal("double_param1", -0.99),
                    ParameterSpec("str_param0", "default"),
                    ParameterSpec("str_param1", "default set in conf file"),
                    ParameterSpec("vector_param0", "0.0,0.1,0.2,0.3,0.4,0.5,0.6") { value ->
                        value.split(',').all { it.trim().toDoubleOrNull() != null }
                    },
                ),
            configurationSets =
                mapOf(
                    "mode0" to
                        mapOf(
                            "int_param0" to "12345",
                            "int_param1" to "98765",
                            "double_param0" to "3.141592653589793238462643383279",
                            "double_param1" to "2.718281828459045235360287471352",
                            "str_param0" to "mode0",
                            "str_param1" to "foo",
                            "vector_param0" to "0.0,0.1,0.2,0.3,0.4",
                        ),
                    "mode1" to
                        mapOf(
                            "int_param0" to "-999",
                            "int_param1" to "999",
                            "double_param0" to "297992458",
                            "double_param1" to "2.97992458e+8",
                            "str_param0" to "mode1",
                            "str_param1" to "AIST",
                            "vector_param0" to "1,2,3,4,5,6,7,8,9",
                        ),
                    "__widget__" to
                        mapOf(
                            "int_param0" to "slider.10",
                            "int_param1" to "spin",
                            "double_param0" to "slider.0.1",
                            "double_param1" to "text",
                            "str_param0" to "radio",
                            "str_param1" to "text",
                            "vector_param0" to "text",
                        ),
                    "__constraints__" to
                        mapOf(
                            "int_param0" to "0<=x<=150",
                            "int_param1" to "0<=x<=1000",
                            "double_param0" to "0<=x<=100",
                            "double_param1" to "",
                            "str_param0" to "(default,mode0,mode1,foo,bar,radio)",
                            "str_param1" to "",
                            "vector_param0" to "",
                        ),
                ),
            category = "example",
            description = "Configuration example component",
        )

    /**
     * OpenRTM-aist's StaticFsm example, the Microwave (`examples/StaticFsm/MicrowaveFsm.cpp`): `Top` holds `Disabled`
     * and `Operational`, which holds `Idle` and `Programmed`, which holds `Cooking`; it starts in `Idle`. `open` (from
     * anywhere `Operational`) disables it, `close` makes it `Operational` again (so `Idle`), `minute` programs it,
     * `start` cooks, `stop` goes back to `Idle`, and `tick` ends the cooking (the example counts minutes down; one is
     * programmed here). It accepts the FSM4RTC observer alone, as OpenRTM-aist C++ 2.0 builds by default (without
     * `OBSERVER_ENABLE`) with its module preloaded.
     */
    public val microwave: ComponentType =
        ComponentType(
            "Microwave",
            observerFlavours = setOf(ObserverFlavour.OMG),
            category = "example",
            description = "Static FSM microwave",
            fsm =
                FsmSpec(
                    "Microwave",
                    parents =
                        mapOf(
                            "Top" to null,
                            "Disabled" to "Top",
                            "Operational" to "Top",
                            "Idle" to "Operational",
                            "Programmed" to "Operational",
                            "Cooking" to "Programmed",
                        ),
                    initial = mapOf("Top" to "Operational", "Operational" to "Idle"),
                    transitions =
                        mapOf(
                            ("Disabled" to "close") to "Operational",
                            ("Operational" to "open") to "Disabled",
                            ("Operational" to "stop") to "Idle",
                            ("Idle" to "minute") to "Programmed",
                            ("Programmed" to "start") to "Cooking",
                            ("Cooking" to "tick") to "Idle",
                        ),
                ),
        )

    /** One [configSample], `ConfigSample0`, inactive, listening on [host]. */
    public fun configSample(naming: String, host: String = "127.0.0.1"): RtSystem =
        rtSystem(naming, host) {
            component(configSample)
        }

    /** A component with an in-port and two out-ports, at 1 Hz so a thousand of them stay cheap. */
    public val relay: ComponentType =
        ComponentType(
            "relay",
            listOf(
                PortSpec.DataIn("in", DataType.TIMED_LONG),
                PortSpec.DataOut("out", DataType.TIMED_LONG),
                PortSpec.DataOut("status", DataType.TIMED_STRING),
            ),
            listOf(fail),
            rate = 1.0,
        )

    /**
     * [count] relay components named `relay0..`, ten per context, spread over nested contexts
     * `<host>.host_cxt/group<i>.grp_cxt/sub<j>.sub_cxt` (ten subgroups per group), listening on [host].
     */
    public fun scale(naming: String, count: Int, type: ComponentType = relay, host: String = "127.0.0.1"): RtSystem =
        rtSystem(naming, host) {
            scaleComponents(count, type)
        }

    /**
     * [scale]'s [count] relays chained into one data flow, `relay<i>:out` to `relay<i+1>:in` (count - 1 connections),
     * inactive: a large system to save, restore, check and start as a whole.
     */
    public fun pipeline(naming: String, count: Int, host: String = "127.0.0.1"): RtSystem =
        rtSystem(naming, host) {
            scaleComponents(count, relay)
            for (index in 1 until count) connect("relay${index - 1}:out", "relay$index:in")
        }

    private fun SystemBuilder.scaleComponents(count: Int, type: ComponentType) {
        repeat(count) { index ->
            val contexts =
                listOf(RuntimeProcess.hostContext, "group${index / 100}.grp_cxt", "sub${index / 10 % 10}.sub_cxt")
            component(type, "${type.typeName}$index", contexts)
        }
    }
}
