package org.rtcoord.osgi;

import org.eclipse.osgi.launch.EquinoxFactory;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.wiring.BundleWiring;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.RtSystem;
import org.rtcoord.runtime.Scenarios;
import org.rtcoord.runtime.naming.NamingService;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.LoggerFactory;

import org.rtcoord.dsl.java.JavaCoordinator;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * rtcoord's bundle in Equinox, RTSystemEditor's framework: it resolves with nothing but the framework
 * (the JRE's packages from the system bundle), starts, and drives a fixture system from inside: discovery,
 * an operation and an event, through the exported API only, loaded by the bundle's class loader, printing
 * nothing; it runs the paper's coordinator, compiled ahead of time, without a Kotlin compiler. Once
 * stopped and uninstalled, none of its threads is left; its logging goes to the framework's SLF4J when
 * there is one; and its API names no type a plug-in cannot see.
 */
class EquinoxTest {
    private static final Set<String> EXPORTED = Set.of("org.rtcoord", "org.rtcoord.java", "org.rtcoord.profile", "org.rtcoord.dsl", "org.rtcoord.dsl.java", "org.rtcoord.dsl.script");

    private NamingService naming;
    private RtSystem system;
    private Framework framework;

    @TempDir
    Path storage;

    @BeforeEach
    void start() {
        naming = NamingService.Companion.start(0, null, "127.0.0.1");
        system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
    }

    /** Equinox with nothing but the JRE's packages, and [extraPackages] of this class path when not empty. */
    private void startFramework(String extraPackages) throws Exception {
        Map<String, String> properties = new HashMap<>(Map.of(
                Constants.FRAMEWORK_STORAGE, storage.toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        if (!extraPackages.isEmpty()) properties.put(Constants.FRAMEWORK_SYSTEMPACKAGES_EXTRA, extraPackages);
        framework = new EquinoxFactory().newFramework(properties);
        framework.start();
    }

    private Bundle installBundle() throws Exception {
        File built = new File(System.getProperty("rtcoord.bundle"));
        assertTrue(Files.exists(built.toPath().resolve("META-INF/MANIFEST.MF")), "no bundle at " + built);
        Bundle bundle = framework.getBundleContext().installBundle("reference:" + built.toURI());
        bundle.start();
        assertEquals(Bundle.ACTIVE, bundle.getState());
        return bundle;
    }

    /** A tree of the fixture system made through the bundle's exported API, as a plug-in would. */
    private AutoCloseable createTree(Bundle bundle) throws Exception {
        Class<?> treeConfig = bundle.loadClass("org.rtcoord.TreeConfig");
        Class<?> javaTree = bundle.loadClass("org.rtcoord.java.JavaTree");
        Object config = treeConfig.getConstructor(List.class).newInstance(List.of(naming.getAddress()));
        return (AutoCloseable) javaTree.getConstructor(treeConfig).newInstance(config);
    }

    @AfterEach
    void stop() throws Exception {
        if (framework != null) {
            framework.stop();
            framework.waitForStop(10_000);
        }
        system.close();
        naming.close();
    }

    @Test
    void theBundleResolvesStartsAndDrivesASystem() throws Exception {
        PrintStream stderr = System.err;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        System.setErr(new PrintStream(printed, true, StandardCharsets.UTF_8));
        try {
            drivesASystem();
        } finally {
            System.setErr(stderr);
        }
        // Before, SLF4J's API alone in the bundle warned that it had no provider: "SLF4J: No SLF4J providers were found."
        assertEquals("", printed.toString(StandardCharsets.UTF_8), "the bundle printed on stderr");
    }

    private void drivesASystem() throws Exception {
        startFramework("");
        Bundle bundle = installBundle();
        Set<String> exported = bundle.adapt(BundleWiring.class).getCapabilities("osgi.wiring.package").stream()
                .map(capability -> (String) capability.getAttributes().get("osgi.wiring.package")).collect(Collectors.toSet());
        assertEquals(EXPORTED, exported);

        // The test runs outside the framework: it reaches the API through the bundle's class loader, as a
        // plug-in importing org.rtcoord.java would.
        Class<?> javaTree = bundle.loadClass("org.rtcoord.java.JavaTree");
        assertFalse(javaTree.getClassLoader() == getClass().getClassLoader());
        ClassLoader loader = bundle.adapt(BundleWiring.class).getClassLoader();
        try (AutoCloseable tree = createTree(bundle)) {
            String host = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext();

            List<?> children = (List<?>) javaTree.getMethod("children", String.class).invoke(tree, host);
            Set<Object> names = children.stream().map(node -> call(node, "getName")).collect(Collectors.toSet());
            assertTrue(names.containsAll(Set.of("laser0.rtc", "gyro0.rtc", "manager.mgr")), names.toString());

            BlockingQueue<String> events = new LinkedBlockingQueue<>();
            Class<?> listener = bundle.loadClass("org.rtcoord.EventListener");
            Object onEvent = Proxy.newProxyInstance(listener.getClassLoader(), new Class<?>[] {listener},
                    (proxy, method, args) -> method.getName().equals("onEvent") ? events.add(String.valueOf(call(args[0], "getNew"))) : null);
            Class<?> stateChanged = bundle.loadClass("org.rtcoord.StateChanged");
            Method subscribe = javaTree.getMethod("subscribe", String.class, Class.class, Executor.class, listener);
            AutoCloseable subscription = (AutoCloseable) subscribe.invoke(tree, host + "/gyro0.rtc", stateChanged, (Executor) Runnable::run, onEvent);

            Object gyro = javaTree.getMethod("component", String.class).invoke(tree, host + "/gyro0.rtc");
            gyro.getClass().getMethod("deactivate").invoke(gyro);
            assertEquals("INACTIVE", String.valueOf(gyro.getClass().getMethod("state").invoke(gyro)));
            assertEquals("INACTIVE", events.poll(10, TimeUnit.SECONDS));
            subscription.close();
        }
        bundle.stop();
        assertEquals(Bundle.RESOLVED, bundle.getState());
        bundle.uninstall();
        // Before, 18 of kotlinx's DefaultDispatcher workers outlived the bundle, and its class loader with them.
        assertEquals(List.of(), threadsLeft(loader, Duration.ofSeconds(20)));
    }

    /**
     * The paper's coordinator, compiled ahead of time on this side (which has the Kotlin compiler), runs in
     * the bundle (which has not): the laser breaks for good and odometry takes over. Stopped, the bundle
     * leaves no thread behind.
     */
    @Test
    void aCompiledCoordinatorRecoversTheLaserInsideTheBundle() throws Exception {
        Path script = Path.of(System.getProperty("rtcoord.root", ".."), "examples", "localisation.coord.kts");
        Path jar = storage.resolve("localisation.jar");
        JavaCoordinator.compile(script, jar);

        startFramework("");
        Bundle bundle = installBundle();
        ClassLoader loader = bundle.adapt(BundleWiring.class).getClassLoader();
        for (String compiler : List.of("kotlin.script.experimental.jvmhost.JvmScriptCompiler", "org.jetbrains.kotlin.cli.common.CLICompiler",
                "kotlin.script.experimental.api.ScriptCompilationConfiguration")) {
            assertThrows(ClassNotFoundException.class, () -> bundle.loadClass(compiler), compiler + " is in the bundle");
        }
        Class<?> javaTree = bundle.loadClass("org.rtcoord.java.JavaTree");
        Class<?> coordinatorClass = bundle.loadClass("org.rtcoord.dsl.java.JavaCoordinator");
        assertFalse(coordinatorClass.getClassLoader() == JavaCoordinator.class.getClassLoader());
        BlockingQueue<String> log = new LinkedBlockingQueue<>();
        String host = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext();
        try (AutoCloseable tree = createTree(bundle);
             AutoCloseable coordinator = (AutoCloseable) coordinatorClass.getMethod("load", javaTree, Path.class, List.class, Consumer.class)
                     .invoke(null, tree, jar, List.of(), (Consumer<String>) log::add)) {
            coordinatorClass.getMethod("start").invoke(coordinator);
            system.component("laser0").breakDown();

            String created = awaitLine(log, line -> line.startsWith("created ") && line.contains("odo_localise0"));
            String localiser = created.substring("created ".length()).split(" ")[0];
            BlockingQueue<String> states = new LinkedBlockingQueue<>();
            Class<?> listener = bundle.loadClass("org.rtcoord.EventListener");
            Object onEvent = Proxy.newProxyInstance(listener.getClassLoader(), new Class<?>[] {listener},
                    (proxy, method, args) -> method.getName().equals("onEvent") ? states.add(String.valueOf(call(args[0], "getNew"))) : null);
            Method subscribe = javaTree.getMethod("subscribe", String.class, Class.class, Executor.class, listener);
            try (AutoCloseable ignored = (AutoCloseable) subscribe.invoke(tree, localiser, bundle.loadClass("org.rtcoord.StateChanged"), (Executor) Runnable::run, onEvent)) {
                Object component = javaTree.getMethod("component", String.class).invoke(tree, localiser);
                if (!"ACTIVE".equals(String.valueOf(component.getClass().getMethod("state").invoke(component)))) {
                    assertEquals("ACTIVE", states.poll(20, TimeUnit.SECONDS), "odo_localise0 did not become ACTIVE; the coordinator said: " + log);
                }
            }
            Object laserLocaliser = javaTree.getMethod("component", String.class).invoke(tree, host + "/laser_localise0.rtc");
            assertEquals("INACTIVE", String.valueOf(laserLocaliser.getClass().getMethod("state").invoke(laserLocaliser)));
        }
        bundle.stop();
        bundle.uninstall();
        assertEquals(List.of(), threadsLeft(loader, Duration.ofSeconds(20)));
    }

    /** The first line of [log] that [wanted] accepts, within 30 s. */
    private static String awaitLine(BlockingQueue<String> log, Predicate<String> wanted) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        List<String> seen = new ArrayList<>();
        for (String line = log.poll(30, TimeUnit.SECONDS); line != null; line = log.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS)) {
            if (wanted.test(line)) return line;
            seen.add(line);
        }
        return fail("no such line within 30 s; the coordinator said: " + seen);
    }

    @Test
    void theBundleLogsThroughTheFrameworksSlf4j() throws Exception {
        ListAppender<ILoggingEvent> logged = new ListAppender<>();
        logged.start();
        Logger library = (Logger) LoggerFactory.getLogger("org.rtcoord");
        Level level = library.getLevel();
        library.setLevel(Level.DEBUG);
        library.addAppender(logged);
        try {
            // This class path's SLF4J, with logback behind it, stands in for Eclipse's slf4j.api and its provider.
            startFramework("org.slf4j;version=2");
            Bundle bundle = installBundle();
            try (AutoCloseable tree = createTree(bundle)) {
                bundle.loadClass("org.rtcoord.java.JavaTree").getMethod("children", String.class).invoke(tree, "/" + naming.getAddress());
            }
            // The tree logs at DEBUG where its ORB listens once it starts; before, the bundle's own SLF4J swallowed it.
            assertTrue(logged.list.stream().anyMatch(event -> event.getLoggerName().equals("org.rtcoord.RtcTree") && event.getFormattedMessage().startsWith("listening on ")),
                    logged.list.toString());
        } finally {
            library.detachAppender(logged);
            library.setLevel(level);
        }
    }

    @Test
    void theExportedApiNamesNoTypeTheBundleKeepsPrivate() throws Exception {
        startFramework("");
        Bundle bundle = installBundle();
        Set<String> exported = EXPORTED;
        List<String> privateTypes = new ArrayList<>();
        for (String name : List.of("org.rtcoord.TreeConfig", "org.rtcoord.TreeConfig$Builder")) {
            for (Method method : bundle.loadClass(name).getMethods()) {
                List<Class<?>> types = new ArrayList<>(List.of(method.getParameterTypes()));
                types.add(method.getReturnType());
                for (Class<?> type : types) {
                    while (type.isArray()) type = type.getComponentType();
                    String packageName = type.getPackageName();
                    if (!type.isPrimitive() && !packageName.startsWith("java.") && !exported.contains(packageName)) {
                        privateTypes.add(name + "." + method.getName() + ": " + type.getName());
                    }
                }
            }
        }
        // Before, TreeConfig.Builder.orb took an org.omg.CORBA.ORB, which no plug-in can name.
        assertEquals(List.of(), privateTypes);
    }

    /**
     * The names of the live threads that hold [loader] (as their context loader, or through their own
     * class) once each has had until [patience] is over to end.
     */
    private static List<String> threadsLeft(ClassLoader loader, Duration patience) throws InterruptedException {
        long deadline = System.nanoTime() + patience.toNanos();
        for (Thread thread : holding(loader)) {
            thread.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
        }
        return holding(loader).stream().map(Thread::getName).sorted().collect(Collectors.toList());
    }

    private static List<Thread> holding(ClassLoader loader) {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(thread -> thread.getContextClassLoader() == loader || thread.getClass().getClassLoader() == loader)
                .collect(Collectors.toList());
    }

    private static Object call(Object target, String getter) {
        try {
            return target.getClass().getMethod(getter).invoke(target);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(getter + " on " + target + ": " + e, e);
        }
    }
}
