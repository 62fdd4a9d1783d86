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
import org.rtcoord.internal.JavaListenerCall;
import org.slf4j.LoggerFactory;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;

import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.stream.Collectors;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What a Java listener throws reaches the handler the host set in its {@link TreeConfig}, written as a Java host writes it. */
class ListenerFailuresTest {
    private final NamingService naming = NamingService.Companion.start(0, null, "127.0.0.1");
    private final RtSystem system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
    private final BlockingQueue<ListenerFailure> failures = new LinkedBlockingQueue<>();
    private final JavaTree tree = new JavaTree(new TreeConfig.Builder().nameServer(naming.getAddress()).listenerFailures(failures::add).build());
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

    @Test
    void anExecutorThatRefusesTheListenersTaskIsHeardOfAndLogged() throws Exception {
        String gyro = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext() + "/gyro0.rtc";
        ListAppender<ILoggingEvent> logged = new ListAppender<>();
        logged.start();
        Logger log = (Logger) LoggerFactory.getLogger(JavaListenerCall.class);
        log.addAppender(logged);
        // SWT's asyncExec once the display is disposed.
        Executor disposed = task -> {
            throw new RejectedExecutionException("Device is disposed");
        };
        EventListener<StateChanged> listener = event -> {
        };
        try (Subscription ignored = tree.subscribe(gyro, StateChanged.class, disposed, listener)) {
            tree.component(gyro).deactivate();
            // Before, the delivery was cancelled in silence: no failure, no log line, and every later event lost too.
            ListenerFailure failure = failures.poll(10, TimeUnit.SECONDS);
            assertNotNull(failure, "the refusal was not reported");
            assertSame(listener, failure.getListener());
            assertInstanceOf(RejectedExecutionException.class, failure.getError());
            assertTrue(failure.getError().getMessage().contains("Device is disposed"), failure.getError().getMessage());
            tree.component(gyro).activate();
            assertNotNull(failures.poll(10, TimeUnit.SECONDS), "the second refusal was not reported");
            List<String> warnings = logged.list.stream().filter(e -> e.getLevel() == Level.WARN).map(ILoggingEvent::getFormattedMessage).collect(Collectors.toList());
            assertEquals(1, warnings.size(), warnings.toString());
            assertTrue(warnings.get(0).contains("gets no more events"), warnings.get(0));
        } finally {
            log.detachAppender(logged);
        }
    }
}
