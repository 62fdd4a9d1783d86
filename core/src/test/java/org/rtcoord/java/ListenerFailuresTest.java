package org.rtcoord.java;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.rtcoord.EventListener;
import org.rtcoord.ListenerFailure;
import org.rtcoord.StateChanged;
import org.rtcoord.Subscription;
import org.rtcoord.TreeConfig;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.RtSystem;
import org.rtcoord.runtime.Scenarios;
import org.rtcoord.runtime.naming.NamingService;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What a Java listener throws reaches the handler the host set in its {@link TreeConfig}, written as a Java host writes it. */
class ListenerFailuresTest {
    private final NamingService naming = NamingService.Companion.start(0, null, "127.0.0.1");
    private final RtSystem system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
    private final BlockingQueue<ListenerFailure> failures = new LinkedBlockingQueue<>();
    private final JavaTree tree = new JavaTree(TreeConfig.builder().nameServer(naming.getAddress()).listenerFailures(failures::add).build());
    private final ExecutorService ui = Executors.newSingleThreadExecutor(runnable -> new Thread(runnable, "ui thread"));

    @AfterEach
    void stop() {
        ui.shutdownNow();
        tree.close();
        system.close();
        naming.close();
    }

    @Test
    void aListenersExceptionOnItsOwnExecutorReachesTheHandlerWithTheListenerAndTheEvent() throws Exception {
        String gyro = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext() + "/gyro0.rtc";
        EventListener<StateChanged> listener = event -> {
            throw new IllegalStateException("listener broke on " + event.getNew());
        };
        try (Subscription ignored = tree.subscribe(gyro, StateChanged.class, ui, listener)) {
            tree.component(gyro).deactivate();
            ListenerFailure failure = failures.poll(10, TimeUnit.SECONDS);
            assertNotNull(failure, "no failure reported");
            assertSame(listener, failure.getListener());
            assertTrue(failure.getEvent() instanceof StateChanged, failure.getEvent().toString());
            assertEquals("listener broke on INACTIVE", failure.getError().getMessage());

            // The listener keeps receiving events, and each failure is reported.
            tree.component(gyro).activate();
            ListenerFailure next = failures.poll(10, TimeUnit.SECONDS);
            assertNotNull(next, "the second failure was not reported");
            assertEquals("listener broke on ACTIVE", next.getError().getMessage());
        }
    }
}
