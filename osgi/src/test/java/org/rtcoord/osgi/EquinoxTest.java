package org.rtcoord.osgi;

import org.eclipse.osgi.launch.EquinoxFactory;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.Constants;
import org.osgi.framework.launch.Framework;
import org.osgi.framework.wiring.BundleWiring;
import org.rtcoord.fixtures.FixtureRuntime;
import org.rtcoord.fixtures.RtSystem;
import org.rtcoord.fixtures.Scenarios;
import org.rtcoord.fixtures.naming.NamingService;

import java.io.File;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * rtcoord's bundle in Equinox, RTSystemEditor's framework: it resolves with nothing but the framework
 * (the JRE's packages from the system bundle), starts, and drives a fixture system from inside: discovery,
 * an operation and an event, through the exported API only, loaded by the bundle's class loader.
 */
class EquinoxTest {
    private NamingService naming;
    private RtSystem system;
    private Framework framework;

    @BeforeEach
    void start(@org.junit.jupiter.api.io.TempDir Path storage) throws Exception {
        naming = NamingService.Companion.start(0, null, "127.0.0.1");
        system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
        framework = new EquinoxFactory().newFramework(Map.of(
                Constants.FRAMEWORK_STORAGE, storage.toString(),
                Constants.FRAMEWORK_STORAGE_CLEAN, Constants.FRAMEWORK_STORAGE_CLEAN_ONFIRSTINIT));
        framework.start();
    }

    @AfterEach
    void stop() throws Exception {
        framework.stop();
        framework.waitForStop(10_000);
        system.close();
        naming.close();
    }

    @Test
    void theBundleResolvesStartsAndDrivesASystem() throws Exception {
        File built = new File(System.getProperty("rtcoord.bundle"));
        assertTrue(Files.exists(built.toPath().resolve("META-INF/MANIFEST.MF")), "no bundle at " + built);
        Bundle bundle = framework.getBundleContext().installBundle("reference:" + built.toURI());
        bundle.start();
        assertEquals(Bundle.ACTIVE, bundle.getState());
        Set<String> exported = bundle.adapt(BundleWiring.class).getCapabilities("osgi.wiring.package").stream()
                .map(capability -> (String) capability.getAttributes().get("osgi.wiring.package")).collect(Collectors.toSet());
        assertEquals(Set.of("org.rtcoord", "org.rtcoord.java", "org.rtcoord.profile"), exported);

        // The test runs outside the framework: it reaches the API through the bundle's class loader, as a
        // plug-in importing org.rtcoord.java would.
        Class<?> treeConfig = bundle.loadClass("org.rtcoord.TreeConfig");
        Class<?> javaTree = bundle.loadClass("org.rtcoord.java.JavaTree");
        assertFalse(javaTree.getClassLoader() == getClass().getClassLoader());
        Object config = treeConfig.getConstructor(List.class).newInstance(List.of(naming.getAddress()));
        try (AutoCloseable tree = (AutoCloseable) javaTree.getMethod("create", treeConfig).invoke(null, config)) {
            String host = "/" + naming.getAddress() + "/" + FixtureRuntime.Companion.getHostContext();

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
    }

    private static Object call(Object target, String getter) {
        try {
            return target.getClass().getMethod(getter).invoke(target);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(getter + " on " + target + ": " + e, e);
        }
    }
}
