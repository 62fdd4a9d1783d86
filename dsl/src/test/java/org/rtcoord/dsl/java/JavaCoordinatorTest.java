package org.rtcoord.dsl.java;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rtcoord.ClosedException;
import org.rtcoord.LifeCycle;
import org.rtcoord.ListenerFailure;
import org.rtcoord.Subscription;
import org.rtcoord.TreeConfig;
import org.rtcoord.dsl.RuleActivity;
import org.rtcoord.dsl.script.ScriptFailure;
import org.rtcoord.fixtures.Await;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.RtSystem;
import org.rtcoord.runtime.Scenarios;
import org.rtcoord.runtime.naming.NamingService;
import org.rtcoord.java.JavaComponent;
import org.rtcoord.java.JavaTree;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.IntConsumer;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A Java tool runs a coordinator script given as text, sees it act on the system, and stops it. */
class JavaCoordinatorTest {
    private NamingService naming;
    private RtSystem system;
    private JavaTree tree;

    @BeforeEach
    void start() {
        naming = NamingService.Companion.start(0, null, "127.0.0.1");
        system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
        tree = new JavaTree(new TreeConfig(List.of(naming.getAddress())));
    }

    @AfterEach
    void stop() {
        tree.close();
        system.close();
        naming.close();
    }

    @Test
    void runsAScriptGivenAsTextAndStopsIt() throws Exception {
        BlockingQueue<String> log = new LinkedBlockingQueue<>();
        String script = "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n";
        JavaComponent gyro = tree.component("/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext() + "/gyro0.rtc");
        try (JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "reset.coord.kts", script, List.of(), log::add)) {
            coordinator.start();
            system.component("gyro0").fail();
            String fired = log.poll(20, TimeUnit.SECONDS);
            assertTrue(fired != null && fired.startsWith("rule 'gyro0.rtc enters ERROR' fired"), String.valueOf(fired));
            Await.await("the rule to reset gyro0", Duration.ofSeconds(10), () -> gyro.state() == LifeCycle.INACTIVE);
            BlockingQueue<Integer> failures = new LinkedBlockingQueue<>();
            coordinator.subscribeFailures(Runnable::run, failures::add);
            assertEquals(0, failures.poll(10, TimeUnit.SECONDS));
        }
        // Stopped: a new failure is left alone. A coordinator started after it, with a rule that only logs, is the
        // marker: once its rule has fired on that failure, the stopped one's would have too.
        log.clear();
        gyro.activate();
        BlockingQueue<String> marker = new LinkedBlockingQueue<>();
        String watching = "on(component(\"gyro0.rtc\")).state(ERROR) { log(\"seen\") }\n";
        try (JavaCoordinator after = JavaCoordinator.fromText(tree, "marker.coord.kts", watching, List.of(), marker::add)) {
            after.start();
            system.component("gyro0").fail();
            Await.await("the marker's rule to fire", Duration.ofSeconds(20),
                () -> marker.stream().anyMatch(line -> line.startsWith("rule 'gyro0.rtc enters ERROR' fired")));
        }
        assertEquals(List.of(), List.copyOf(log));
    }

    @Test
    void aJavaListenerFollowsEachRulesStatus() throws Exception {
        BlockingQueue<String> statuses = new LinkedBlockingQueue<>();
        BlockingQueue<Integer> failures = new LinkedBlockingQueue<>();
        String script = "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n";
        try (JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "reset.coord.kts", script)) {
            coordinator.subscribeRules(Runnable::run, (rule, status) -> statuses.add(rule + ": " + status.getFirings()));
            Subscription counted = coordinator.subscribeFailures(Runnable::run, failures::add);
            assertEquals(0, failures.poll(10, TimeUnit.SECONDS));
            counted.close();
            coordinator.start();
            assertEquals("gyro0.rtc enters ERROR: 0", statuses.poll(10, TimeUnit.SECONDS));
            system.component("gyro0").fail();
            assertEquals("gyro0.rtc enters ERROR: 1", statuses.poll(20, TimeUnit.SECONDS));
        }
    }

    @Test
    void aClosedCoordinatorSaysItIsClosed() throws Exception {
        JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "idle.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n");
        coordinator.start();
        coordinator.close();
        // Before, kotlinx's JobCancellationException; then "coordinator: closed", not saying which.
        ClosedException closed = assertThrows(ClosedException.class, coordinator::start);
        assertEquals("coordinator idle.coord.kts: closed", closed.getMessage());
        ExecutionException async = assertThrows(ExecutionException.class, () -> coordinator.startAsync().get(10, TimeUnit.SECONDS));
        assertInstanceOf(ClosedException.class, async.getCause());
    }

    @Test
    void aJavaListenerFollowsEachSupervisor() throws Exception {
        BlockingQueue<String> statuses = new LinkedBlockingQueue<>();
        String script = "supervise(component(\"gyro0.rtc\"))\n";
        try (JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "supervise.coord.kts", script)) {
            coordinator.start();
            coordinator.subscribeSupervisors(Runnable::run, (name, status) -> {
                Duration backoff = status.getBackoff();
                statuses.add(status.getChildren().size() + " child, backoff " + backoff);
            });
            assertEquals("1 child, backoff null", statuses.poll(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void aCoordinatorCompiledAheadOfTimeRunsFromItsJar(@TempDir Path directory) throws Exception {
        Path script = Files.writeString(directory.resolve("reset.coord.kts"), "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n");
        Path jar = directory.resolve("reset.jar");
        JavaCoordinator.compile(script, jar);
        Files.delete(script);
        BlockingQueue<String> log = new LinkedBlockingQueue<>();
        try (JavaCoordinator coordinator = JavaCoordinator.load(tree, jar, List.of(), log::add)) {
            coordinator.start();
            system.component("gyro0").fail();
            String fired = log.poll(20, TimeUnit.SECONDS);
            assertTrue(fired != null && fired.startsWith("rule 'gyro0.rtc enters ERROR' fired"), String.valueOf(fired));
        }
    }

    @Test
    void aSupervisorIsFollowedFromBeforeTheStart() throws Exception {
        BlockingQueue<String> statuses = new LinkedBlockingQueue<>();
        try (JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "supervise.coord.kts", "supervise(component(\"gyro0.rtc\"))\n")) {
            // Before, a listener subscribed before start() was never called: there were no supervisors yet.
            coordinator.subscribeSupervisors(Runnable::run, (name, status) -> statuses.add(status.getChildren().size() + " child"));
            assertEquals("0 child", statuses.poll(10, TimeUnit.SECONDS));
            coordinator.start();
            assertEquals("1 child", statuses.poll(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void theCoordinatorRunsOnItsTreesThreadsNotKotlinxSharedOnes() throws Exception {
        BlockingQueue<String> threads = new LinkedBlockingQueue<>();
        String script = "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n";
        try (JavaCoordinator coordinator = JavaCoordinator.fromText(tree, "reset.coord.kts", script, List.of(), line -> threads.add("log: " + Thread.currentThread().getName()))) {
            coordinator.subscribeRules(Runnable::run, (rule, status) -> threads.add("rules: " + Thread.currentThread().getName()));
            coordinator.start();
            system.component("gyro0").fail();
            // Before, both ran on kotlinx's DefaultDispatcher workers, which outlive the coordinator (and an OSGi bundle).
            for (String seen = threads.poll(20, TimeUnit.SECONDS); ; seen = threads.poll(20, TimeUnit.SECONDS)) {
                assertTrue(seen != null && seen.matches("(log|rules): rtcoord-(tree|call)-\\d+( @.*)?"), String.valueOf(seen));
                if (seen.startsWith("log: ")) break;
            }
        }
    }

    @Test
    void aListenerThatThrowsOrIsRefusedReachesTheTreesFailureHandler() throws Exception {
        BlockingQueue<ListenerFailure> heard = new LinkedBlockingQueue<>();
        TreeConfig config = new TreeConfig.Builder().nameServer(naming.getAddress()).listenerFailures(heard::add).build();
        try (JavaTree hooked = new JavaTree(config);
             JavaCoordinator coordinator = JavaCoordinator.fromText(hooked, "reset.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")) {
            BiConsumer<String, RuleActivity.Status> throwing = (rule, status) -> { throw new IllegalStateException("view gone"); };
            coordinator.subscribeRules(Runnable::run, throwing);
            // Before, only logged: the handler never heard of it.
            ListenerFailure failure = heard.poll(10, TimeUnit.SECONDS);
            assertNotNull(failure, "the tree's listener failure handler did not hear of the listener's failure");
            assertSame(throwing, failure.getListener());
            assertEquals("view gone", failure.getError().getMessage());
            assertEquals("gyro0.rtc enters ERROR", ((Map.Entry<?, ?>) failure.getEvent()).getKey());
            // An executor that refuses (SWT's display disposed) loses no change without the handler hearing of it.
            IntConsumer counter = count -> { };
            coordinator.subscribeFailures(task -> { throw new RejectedExecutionException("display disposed"); }, counter);
            ListenerFailure refused = heard.poll(10, TimeUnit.SECONDS);
            assertNotNull(refused, "the tree's listener failure handler did not hear of the refusal");
            assertSame(counter, refused.getListener());
            assertInstanceOf(RejectedExecutionException.class, refused.getError());
        }
    }

    @Test
    void aBrokenScriptIsOneLinePerProblem() {
        ScriptFailure failure = assertThrows(ScriptFailure.class,
                () -> JavaCoordinator.fromText(tree, "broken.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) {\n    resett()\n}\n"));
        assertTrue(failure.getMessage().startsWith("broken.coord.kts:2:5: "), failure.getMessage());
    }
}
