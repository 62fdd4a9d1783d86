package org.rtcoord.idl;

import java.util.Properties;

/**
 * The one JacORB configuration of rtcoord: the tree's ORB and the fixtures' ORBs are both made from it,
 * so what the benchmarks measure on the fixtures is what the tree runs with. Every figure quoted below
 * was measured by {@code scripts/bench} (see bench/README.md, "where the time goes").
 */
public final class OrbRecipe {
  private OrbRecipe() {}

  /** How many request threads an ORB's POAs have at most, and by default all the time. */
  public static final int REQUEST_THREADS = 64;

  /**
   * The properties of an ORB listening on {@code host} only (and on {@code port}, or one the system
   * chooses for 0), whose every outgoing call times out after {@code callTimeoutMillis}.
   */
  public static Properties properties(String host, int port, long callTimeoutMillis) {
    return properties(host, port, callTimeoutMillis, REQUEST_THREADS);
  }

  /**
   * As {@link #properties(String, int, long)}, with {@code idleRequestThreads} of the {@link #REQUEST_THREADS}
   * request threads started with the first request and kept; the others are started when a request finds every
   * thread busy, and end once it is served. For an ORB that serves a few components, made and ended many times
   * a minute: a simulated system, each run of an exploration.
   */
  public static Properties properties(
      String host, int port, long callTimeoutMillis, int idleRequestThreads) {
    if (idleRequestThreads < 1 || idleRequestThreads > REQUEST_THREADS) {
      throw new IllegalArgumentException(
          "idleRequestThreads must be 1 to " + REQUEST_THREADS + ", was " + idleRequestThreads);
    }
    Properties properties = new Properties();
    properties.setProperty("org.omg.CORBA.ORBClass", "org.jacorb.orb.ORB");
    properties.setProperty("org.omg.CORBA.ORBSingletonClass", "org.jacorb.orb.ORBSingleton");
    // Binds the listener to this address alone, and it is the only one the references carry.
    properties.setProperty("OAIAddr", host);
    if (port != 0) properties.setProperty("OAPort", Integer.toString(port));
    // Calls between ORBs of one JVM go over TCP like any other, not through in-memory pipes.
    properties.setProperty("jacorb.iiop.enable_loopback", "off");
    // A refused connection fails at once (default: five retries, 2.5 s); a host that never completes the
    // TCP handshake fails at the call deadline instead of after 90 s.
    properties.setProperty("jacorb.retries", "0");
    String timeout = Long.toString(callTimeoutMillis);
    properties.setProperty("jacorb.connection.client.connect_timeout", timeout);
    // The deadline of every call, kept by the waiting thread itself. A RELATIVE_RT_TIMEOUT policy would
    // do the same at three times the cost per call: JacORB arms a timer for each request.
    properties.setProperty("jacorb.connection.client.pending_reply_timeout", timeout);
    // One pool of request threads for every POA of the ORB, by default all started with the first request. JacORB
    // starts a missing thread while holding the pool's lock, which every thread that finished a request
    // needs to go back to the pool: under load the pool emptied itself, started threads up to the
    // limit and warned "thread pool exhausted" for every request (a fixture serving 1000 components:
    // 104 of 128 request threads blocked returning to the pool). Started at once, none is ever started
    // under that lock. 64: a tree keeps at most 32 calls in flight (TreeConfig.concurrency) and 32 poll
    // reads, and a component's hung execution context holds a thread per call until the caller's deadline.
    // A simulated system is made afresh for each run of an exploration: starting 64 threads for each of
    // its ORBs, and ending them, was a fifth of the runs' CPU, so it keeps fewer idle.
    properties.setProperty("jacorb.poa.thread_pool_shared", "on");
    properties.setProperty("jacorb.poa.thread_pool_min", Integer.toString(idleRequestThreads));
    properties.setProperty("jacorb.poa.thread_pool_max", Integer.toString(REQUEST_THREADS));
    // Requests beyond what the threads take wait for room rather than failing TRANSIENT: a busy ORB
    // answers late, it never refuses. Observer hints, which a single thread takes in order, would
    // otherwise be lost (a oneway sender never sees the TRANSIENT).
    properties.setProperty("jacorb.poa.queue_wait", "on");
    properties.setProperty("jacorb.poa.queue_max", "1000");
    // A connection's reader thread goes back to a pool when the connection closes, and JacORB keeps five
    // of them idle on each side for as long as the ORB runs: a coordinator that other trees once probed
    // (they ask whether its observers on a shared component still answer) kept them for months. One is
    // kept; a new connection starts its reader again.
    properties.setProperty("jacorb.connection.server.max_idle_receptor_threads", "1");
    properties.setProperty("jacorb.connection.client.max_idle_receptor_threads", "1");
    // Buffer pools of the ORB's own: another ORB's destroy empties JacORB's shared ones under this one.
    properties.setProperty("jacorb.buffermanager.factory", OrbBufferPools.class.getName());
    return properties;
  }
}
