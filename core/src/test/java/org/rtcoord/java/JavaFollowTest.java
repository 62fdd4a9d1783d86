package org.rtcoord.java;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.rtcoord.PortTraffic;
import org.rtcoord.RtcEvent;
import org.rtcoord.StateChanged;
import org.rtcoord.Subscription;
import org.rtcoord.SystemSnapshot;
import org.rtcoord.TreeConfig;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.RtSystem;
import org.rtcoord.runtime.Scenarios;
import org.rtcoord.runtime.naming.NamingService;

import java.util.List;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/** A Java view follows several kinds of event from one snapshot, as a system editor draws states and traffic. */
class JavaFollowTest {
    private final NamingService naming = NamingService.Companion.start(0, null, "127.0.0.1");
    private final RtSystem system = Scenarios.INSTANCE.localisation(naming.getCorbaloc(), "127.0.0.1");
    private final JavaTree tree = new JavaTree(new TreeConfig(List.of(naming.getAddress())));

    @AfterEach
    void stop() {
        tree.close();
        system.close();
        naming.close();
    }

    @Test
    void statesAndPortTrafficFollowOneSnapshot() throws Exception {
        String laser = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext() + "/laser0.rtc";
        CompletableFuture<SystemSnapshot> started = new CompletableFuture<>();
        BlockingQueue<RtcEvent> events = new LinkedBlockingQueue<>();
        // Before, follow took one event type: a view had two snapshots, and the events between them in neither.
        try (Subscription ignored = tree.follow(List.of(laser), Set.of(StateChanged.class, PortTraffic.class), Runnable::run, started::complete, events::add)) {
            long begun = started.get(10, TimeUnit.SECONDS).getSequence();
            PortTraffic traffic = next(events, PortTraffic.class);
            assertTrue(traffic.getSequence() > begun, "traffic from before the snapshot: " + traffic);
            tree.component(laser).deactivate();
            StateChanged deactivated = next(events, StateChanged.class);
            assertTrue(deactivated.getSequence() > begun, "a state from before the snapshot: " + deactivated);
        }
    }

    private static <E extends RtcEvent> E next(BlockingQueue<RtcEvent> events, Class<E> type) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            RtcEvent event = events.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
            if (type.isInstance(event)) return type.cast(event);
        }
        return fail("no " + type.getSimpleName() + " within 10 s");
    }
}
