package org.rtcoord.java;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.rtcoord.ClosedException;
import org.rtcoord.NotFoundException;
import org.rtcoord.RtcException;
import org.rtcoord.TimedOutException;
import org.rtcoord.TreeConfig;
import org.rtcoord.runtime.RuntimeProcess;
import org.rtcoord.runtime.naming.NamingService;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A Java caller's blocking calls behave as Java's own do: giving up on one (cancelling its future,
 * interrupting its thread) ends it at once and holds up no later call, even on a name server that
 * accepts connections and never answers; a failure shows the caller's frames; a closed tree says so.
 */
class BlockingCallsTest {
    private static final Duration CALL_TIMEOUT = Duration.ofSeconds(2);

    private final ExecutorService background = Executors.newCachedThreadPool();
    private final List<Socket> accepted = new CopyOnWriteArrayList<>();
    /** One entry for each request the silent name server received (its first bytes on a connection). */
    private final BlockingQueue<Socket> requests = new LinkedBlockingQueue<>();
    private ServerSocket silent;
    private JavaTree tree;

    @BeforeEach
    void start() throws IOException {
        silent = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        background.execute(this::acceptAndNeverAnswer);
        tree = new JavaTree(new TreeConfig.Builder().callTimeout(CALL_TIMEOUT).build());
    }

    @AfterEach
    void stop() throws IOException {
        tree.close();
        silent.close();
        for (Socket socket : accepted) socket.close();
        background.shutdownNow();
    }

    private String silentServer() {
        return "/127.0.0.1:" + silent.getLocalPort();
    }

    private void acceptAndNeverAnswer() {
        try {
            while (true) {
                Socket socket = silent.accept();
                accepted.add(socket);
                background.execute(() -> {
                    try {
                        InputStream in = socket.getInputStream();
                        byte[] buffer = new byte[4096];
                        while (in.read(buffer) > 0) requests.add(socket);
                    } catch (IOException closed) {
                        // The test is over.
                    }
                });
            }
        } catch (IOException closed) {
            // The test is over.
        }
    }

    private void awaitARequest() throws InterruptedException {
        assertNotNull(requests.poll(10, TimeUnit.SECONDS), "the silent name server got no request");
    }

    @Test
    void aCancelledCallHoldsUpNoLaterCall() throws Exception {
        CompletableFuture<List<JavaNode>> first = tree.childrenAsync(silentServer());
        awaitARequest();
        assertTrue(first.cancel(true));

        long started = System.nanoTime();
        TimedOutException timedOut = assertThrows(TimedOutException.class, () -> tree.children(silentServer()));
        long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        // Its own deadline, not the cancelled call's as well: before, it waited for that one first (twice as long).
        assertTrue(tookMillis < CALL_TIMEOUT.toMillis() * 3 / 2, "the call after a cancelled one took " + tookMillis + " ms: " + timedOut.getMessage());
    }

    @Test
    void anInterruptedCallThrowsInterruptedExceptionAtOnce() throws Exception {
        CompletableFuture<Throwable> outcome = new CompletableFuture<>();
        Thread caller = new Thread(() -> {
            try {
                tree.children(silentServer());
                outcome.complete(null);
            } catch (Throwable e) {
                outcome.complete(e);
            }
        }, "blocked caller");
        caller.start();
        awaitARequest();
        long interrupted = System.nanoTime();
        caller.interrupt();
        Throwable thrown = outcome.get(CALL_TIMEOUT.toMillis() / 2, TimeUnit.MILLISECONDS);
        assertInstanceOf(InterruptedException.class, thrown);
        assertTrue(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - interrupted) < CALL_TIMEOUT.toMillis() / 2);
        caller.join(10_000);
    }

    @Test
    void aFailureShowsTheCallersFrames() throws Exception {
        NamingService naming = NamingService.Companion.start(0, null, "127.0.0.1");
        try {
            String missing = "/" + naming.getAddress() + "/" + RuntimeProcess.Companion.getHostContext() + "/nothing0.rtc";
            NotFoundException notFound = assertThrows(NotFoundException.class, () -> tree.component(missing));
            assertTrue(Arrays.stream(notFound.getStackTrace()).anyMatch(frame -> frame.getMethodName().equals("aFailureShowsTheCallersFrames")),
                    "no caller frame in " + Arrays.toString(notFound.getStackTrace()));
        } finally {
            naming.close();
        }
    }

    @Test
    void aClosedTreeSaysItIsClosed() throws Exception {
        CompletableFuture<List<JavaNode>> pending = tree.childrenAsync(silentServer());
        awaitARequest();
        tree.close();

        ExecutionException underway = assertThrows(ExecutionException.class, () -> pending.get(10, TimeUnit.SECONDS));
        assertInstanceOf(ClosedException.class, underway.getCause());
        ClosedException closed = assertThrows(ClosedException.class, () -> tree.children("/"));
        assertEquals("tree: closed", closed.getMessage());
        ExecutionException later = assertThrows(ExecutionException.class, () -> tree.nodeAsync("/").get(10, TimeUnit.SECONDS));
        assertInstanceOf(ClosedException.class, later.getCause());
    }

    @Test
    void findOnADeadNameServerFailsAsChildrenDoes() throws Exception {
        int nothingListens;
        try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            nothingListens = probe.getLocalPort();
        }
        String dead = "/127.0.0.1:" + nothingListens;
        RtcException listing = assertThrows(RtcException.class, () -> tree.children(dead));
        RtcException found = assertThrows(RtcException.class, () -> tree.find("/", node -> true));
        assertEquals(listing.getMessage(), found.getMessage());
        assertEquals(listing.getMessage(), assertThrows(RtcException.class, () -> tree.find(dead, node -> true)).getMessage());
    }
}
