package org.rtcoord.java;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rtcoord.ConnectorSnapshot;
import org.rtcoord.EventOptions;
import org.rtcoord.LifeCycle;
import org.rtcoord.LogInput;
import org.rtcoord.LogRecord;
import org.rtcoord.NodeKind;
import org.rtcoord.NotFoundException;
import org.rtcoord.ParameterChanged;
import org.rtcoord.PortData;
import org.rtcoord.PreconditionNotMetException;
import org.rtcoord.RtcException;
import org.rtcoord.StateChanged;
import org.rtcoord.Subscription;
import org.rtcoord.TimedDoubleSeq;
import org.rtcoord.TransitionOutcome;
import org.rtcoord.TreeConfig;
import org.rtcoord.WatchMode;
import org.rtcoord.fixtures.Await;
import org.rtcoord.runtime.FluentLogSender;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.RtSystem;
import org.rtcoord.runtime.Scenarios;
import org.rtcoord.runtime.naming.NamingService;
import org.rtcoord.profile.ProfileFormatException;
import org.rtcoord.profile.ProfileRefusedException;
import org.rtcoord.profile.RtsProfile;
import org.rtcoord.profile.RtsProfiles;

import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * What a Java tool embedding rtcoord does (RTSystemEditor's operations), written in Java against the
 * fixtures' localisation system: if this compiles and passes, the API reads and works from Java.
 */
class JavaEmbeddingTest {
    private NamingService naming;
    private RtSystem system;
    private JavaTree tree;
    private String host;

    @BeforeEach
    void start() {
        naming = NamingService.Companion.start(0, null, "127.0.0.1");
        system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
        TreeConfig config = new TreeConfig.Builder()
                .nameServer(naming.getAddress())
                .callTimeout(Duration.ofSeconds(5))
                .build();
        tree = new JavaTree(config);
        host = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext();
    }

    @AfterEach
    void stop() {
        tree.close();
        system.close();
        naming.close();
    }

    private String path(String name) {
        return host + "/" + name;
    }

    @Test
    void configuresATreeAsJavaWritesIt() {
        TreeConfig plain = new TreeConfig(List.of("127.0.0.1:2810"));
        assertEquals(List.of("127.0.0.1:2810"), plain.getNameServers());
        assertEquals(3000, plain.getCallTimeoutMillis());
        assertEquals(5000, tree.getConfig().getCallTimeoutMillis());
        EventOptions options = new EventOptions.Builder().mode(WatchMode.POLL).pollPeriod(Duration.ofMillis(200)).build();
        assertEquals(200, options.getPollPeriodMillis());
        assertEquals(1000, new EventOptions().getHeartbeatMillis());
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> new TreeConfig.Builder().callTimeout(Duration.ZERO).build());
        assertEquals("callTimeout must be positive, was 0s", bad.getMessage());
    }

    @Test
    void listsTheSystem() throws RtcException, InterruptedException {
        Set<String> names = tree.children(host).stream().map(JavaNode::getName).collect(Collectors.toSet());
        assertTrue(names.containsAll(Set.of("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc", "manager.mgr")), names.toString());

        List<JavaNode> components = tree.find("/", node -> node.getKind() == NodeKind.COMPONENT && node.getPath().startsWith(host + "/"));
        assertEquals(Set.of("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc"),
                components.stream().map(JavaNode::getName).collect(Collectors.toSet()));

        NotFoundException missing = assertThrows(NotFoundException.class, () -> tree.component(path("sonar0.rtc")));
        assertEquals(path("sonar0.rtc") + ": not found", missing.getMessage());
    }

    @Test
    void activatesAndDeactivatesBlockingAndAsync() throws Exception {
        JavaComponent laser = tree.component(path("laser0.rtc"));
        assertEquals(LifeCycle.ACTIVE, laser.state());
        laser.deactivate();
        assertEquals(LifeCycle.INACTIVE, laser.state());
        assertThrows(PreconditionNotMetException.class, laser::deactivate);

        TransitionOutcome started = laser.activateAsync().get(10, TimeUnit.SECONDS);
        assertEquals(LifeCycle.ACTIVE, started.getState());
        assertFalse(started.isSlow(), started.toString());
        assertEquals(LifeCycle.ACTIVE, laser.stateAsync().get(10, TimeUnit.SECONDS));
        assertEquals(LifeCycle.ACTIVE, laser.snapshot().getState());
    }

    @Test
    void disconnectsAndConnectsPorts() throws RtcException, InterruptedException {
        JavaPort out = tree.port(path("laser0.rtc:laser"));
        JavaPort in = tree.port(path("laser_localise0.rtc:laser"));
        assertEquals(1, out.connections().size());

        out.disconnectAll();
        assertEquals(List.of(), out.connections());
        assertEquals(List.of(), in.snapshot().getConnectors());

        ConnectorSnapshot made = out.connect(List.of(in), Map.of("dataport.subscription_type", "new"), "from_java");
        assertEquals("from_java", made.getName());
        assertEquals("new", made.getProperties().get("dataport.subscription_type"));
        assertEquals(List.of(made.getId()), in.connections().stream().map(c -> c.getId()).collect(Collectors.toList()));

        in.disconnect(made.getId());
        assertEquals(List.of(), out.connections());
    }

    @Test
    void tapsAnOutPortsData() throws Exception {
        JavaPort laser = tree.port(path("laser0.rtc:laser"));
        BlockingQueue<PortData> samples = new LinkedBlockingQueue<>();
        Subscription subscription = laser.tapAsync(samples::add).get(10, TimeUnit.SECONDS);
        PortData sample = samples.poll(5, TimeUnit.SECONDS);
        assertTrue(sample instanceof TimedDoubleSeq, "a scan: " + sample);
        assertEquals(8, ((TimedDoubleSeq) sample).getData().size());
        assertNotNull(sample.getTime());
        assertEquals(1, laser.connections().stream().filter(c -> c.getId().startsWith("rtcoord-tap-")).count());
        subscription.cancel();
        Await.await("the tap removed once cancelled", Duration.ofSeconds(10),
                () -> laser.connections().stream().noneMatch(c -> c.getId().startsWith("rtcoord-tap-")));
    }

    @Test
    void readsAndChangesConfiguration() throws Exception {
        JavaComponent localiser = tree.component(path("laser_localise0.rtc"));
        assertEquals("1.0", localiser.configuration().value("gain"));

        localiser.setParameter("gain", "2.5");
        assertEquals("2.5", localiser.configuration().value("gain"));
        awaitGain("2.5");

        localiser.activateConfigurationSetAsync("precise").get(10, TimeUnit.SECONDS);
        assertEquals("precise", localiser.configuration().getActiveSet());
        awaitGain("0.5");

        // OpenRTM-aist never checks constraints: a value outside one is written, with a warning, unless strict.
        RtcException refused = assertThrows(RtcException.class, () -> localiser.setParameter("gain", "12", null, true));
        assertTrue(refused.getMessage().contains("0<x<10"), refused.getMessage());
        assertEquals("0.5", localiser.configuration().value("gain"), "a strict refusal changes nothing");
        List<String> warnings = localiser.setParameter("gain", "12");
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).contains("0<x<10"), warnings.toString());
        assertEquals("12", localiser.configuration().value("gain"));
    }

    /** Waits until the component applies [gain]: as OpenRTM-aist, it does so on its execution thread, a cycle later. */
    private void awaitGain(String gain) {
        Await.await("laser_localise0 to apply gain " + gain, Duration.ofSeconds(10),
                () -> system.component("laser_localise0").parameter("gain").equals(gain));
    }

    @Test
    void createsAndDeletesAComponentThroughAManager() throws RtcException, InterruptedException {
        JavaManager master = tree.manager(path("manager.mgr"));
        assertTrue(master.isMaster());
        JavaComponent created = master.create("odo_localise", "from_java");
        assertEquals("from_java", created.snapshot().getInstanceName());
        assertEquals(LifeCycle.INACTIVE, created.state());
        assertTrue(tree.children(host).stream().anyMatch(node -> node.getName().equals("from_java.rtc")));

        master.delete("from_java");
        tree.refresh(host);
        assertFalse(tree.children(host).stream().anyMatch(node -> node.getName().equals("from_java.rtc")));
    }

    @Test
    void deliversEventsOnTheCallersExecutor() throws Exception {
        ExecutorService ui = Executors.newSingleThreadExecutor(runnable -> new Thread(runnable, "ui thread"));
        try {
            BlockingQueue<String> seen = new LinkedBlockingQueue<>();
            Subscription states = tree.subscribe(path("gyro0.rtc"), StateChanged.class, ui,
                    event -> seen.add(threadKind() + ": " + event.getOld() + " -> " + event.getNew()));
            Subscription parameters = tree.subscribeAsync(path("laser_localise0.rtc"), ParameterChanged.class, ui,
                    event -> seen.add(threadKind() + ": " + event.getName() + "=" + event.getNew()),
                    new EventOptions.Builder().mode(WatchMode.POLL).pollPeriod(Duration.ofMillis(100)).build()).get(10, TimeUnit.SECONDS);

            tree.component(path("gyro0.rtc")).deactivate();
            assertEquals("ui thread: ACTIVE -> INACTIVE", seen.poll(10, TimeUnit.SECONDS));
            tree.component(path("laser_localise0.rtc")).setParameter("gain", "3");
            assertEquals("ui thread: gain=3", seen.poll(10, TimeUnit.SECONDS));

            states.close();
            parameters.close();
            // A subscription made after the close is the marker: once it has seen the activation on the UI thread,
            // and that thread has run what was queued behind it, a closed subscription's delivery would be in seen.
            BlockingQueue<String> marker = new LinkedBlockingQueue<>();
            try (Subscription after = tree.subscribe(path("gyro0.rtc"), StateChanged.class, ui,
                    event -> marker.add(event.getOld() + " -> " + event.getNew()))) {
                tree.component(path("gyro0.rtc")).activate();
                assertEquals("INACTIVE -> ACTIVE", marker.poll(10, TimeUnit.SECONDS));
            }
            ui.submit(() -> { }).get(10, TimeUnit.SECONDS);
            assertEquals(List.of(), List.copyOf(seen));
        } finally {
            ui.shutdownNow();
        }
    }

    @Test
    void receivesComponentsLogRecordsAsEvents() throws Exception {
        ExecutorService ui = Executors.newSingleThreadExecutor(runnable -> new Thread(runnable, "ui thread"));
        LogInput input = tree.listenForLogs("127.0.0.1:0");
        try (FluentLogSender sender = new FluentLogSender(new InetSocketAddress(input.getHost(), input.getPort()), "manager_slave", "rtclog")) {
            BlockingQueue<String> seen = new LinkedBlockingQueue<>();
            try (Subscription records = tree.subscribe(path("laser0.rtc"), LogRecord.class, ui,
                    record -> seen.add(threadKind() + ": " + record.getLevel() + " " + record.getMessage()))) {
                assertTrue(sender.send("laser0", "WARN", "scan timeout"));
                assertEquals("ui thread: WARN scan timeout", seen.poll(10, TimeUnit.SECONDS));
                assertEquals(1, input.getReceived());
            }
        } finally {
            ui.shutdownNow();
        }
    }

    /** Whether the caller runs on the test's "UI" thread (coroutine debugging may append to thread names). */
    private static String threadKind() {
        return Thread.currentThread().getName().startsWith("ui thread") ? "ui thread" : "another thread";
    }

    @Test
    void failuresAreTheOperationsOwnExceptions() throws Exception {
        JavaComponent gyro = tree.component(path("gyro0.rtc"));
        var failed = gyro.activateAsync();
        var thrown = assertThrows(java.util.concurrent.ExecutionException.class, () -> failed.get(10, TimeUnit.SECONDS));
        assertTrue(thrown.getCause() instanceof PreconditionNotMetException, thrown.getCause().toString());
        assertNotNull(tree.node(path("gyro0.rtc")));
    }

    /** Java catches each checked exception by its type: a {@code catch} of one the method does not declare does not compile. */
    @Test
    void aRefusedRestoreIsCaughtAsProfileRefusedException() throws Exception {
        JavaSystemProfiles profiles = new JavaSystemProfiles(tree);
        RtsProfile saved = profiles.save();
        tree.component(path("gyro0.rtc")).exit();
        try {
            profiles.restore(saved);
            fail("restored a profile whose component is gone");
        } catch (ProfileRefusedException refused) {
            assertTrue(refused.getReason().contains("gyro0.rtc is not running"), refused.getReason());
        }
    }

    @Test
    void aMissingProfileFileIsCaughtAsProfileFormatException(@TempDir Path directory) {
        Path missing = directory.resolve("missing.xml");
        try {
            RtsProfiles.read(missing);
            fail("read a file that is not there");
        } catch (ProfileFormatException unreadable) {
            assertEquals(missing.toString(), unreadable.getSource());
            assertTrue(unreadable.getMessage().startsWith(missing + ": cannot read"), unreadable.getMessage());
        }
    }
}
