package org.rtcoord.bench.jmh;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.jacorb.orb.ORB;
import org.omg.CosNaming.NamingContextExtHelper;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.infra.BenchmarkParams;
import org.openjdk.jmh.infra.IterationParams;
import org.openjdk.jmh.runner.IterationType;
import org.rtcoord.idl.OrbRecipe;

/**
 * The cost of one remote call and one notification as the tree makes and takes them, on an ORB of
 * rtcoord's recipe ({@link OrbRecipe}), in this forked JVM. The bench JVM that forked it
 * ({@code MicroBench}) passes, as system properties, the naming address of a fixture JVM, the name of
 * one of its components, which a tree in the bench JVM watches by push, and the fixture JVM's process id.
 *
 * <p>Besides JMH's time per call, each measured iteration appends to the file
 * {@code rtcoord.bench.cpu} the process CPU time per call of the coordinator's side and of the
 * component's side: for reads the coordinator is this JVM and the component the fixture JVM; for a
 * notification the component is this JVM (it sends, as a component's observer hub does) and the
 * coordinator the bench JVM, whose tree receives it.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class RemoteCallBenchmark {
  private ORB orb;
  private RTC.RTObject component;
  private RTC.ExecutionContext context;
  private OpenRTM.ComponentObserver observer;
  private ProcessHandle fixtures;
  private ProcessHandle coordinator;
  private long calls;
  private long ownCpuBefore;
  private long peerCpuBefore;

  @Setup(Level.Trial)
  public void connect() {
    orb = (ORB) org.omg.CORBA.ORB.init(new String[0], OrbRecipe.properties("127.0.0.1", 0, 3000));
    var naming = NamingContextExtHelper.narrow(orb.string_to_object("corbaloc:iiop:" + property("naming") + "/NameService"));
    try {
      component = RTC.RTObjectHelper.narrow(naming.resolve_str(property("component")));
    } catch (org.omg.CORBA.UserException e) {
      throw new IllegalStateException("no component " + property("component"), e);
    }
    context = component.get_owned_contexts()[0];
    observer = treeObserver();
    fixtures = ProcessHandle.of(Long.parseLong(property("fixtures.pid"))).orElseThrow();
    coordinator = ProcessHandle.current().parent().orElseThrow();
  }

  /** The observer the bench JVM's tree attached to the component, found among its service profiles. */
  private OpenRTM.ComponentObserver treeObserver() {
    try {
      for (_SDOPackage.ServiceProfile profile : component.get_service_profiles()) {
        // Either flavour takes the same request (HEARTBEAT is 5 in both): no _is_a round trip to find out which.
        if (profile.id.startsWith("rtcoord-observer-")) return OpenRTM.ComponentObserverHelper.unchecked_narrow(profile.service);
      }
    } catch (org.omg.CORBA.UserException e) {
      throw new IllegalStateException("cannot read the service profiles of " + property("component"), e);
    }
    throw new IllegalStateException("no rtcoord observer attached to " + property("component"));
  }

  @TearDown(Level.Trial)
  public void disconnect() {
    orb.shutdown(false);
    orb.destroy();
  }

  /** What a poll tick of a component watched for its state reads: one context's state. */
  @Benchmark
  public RTC.LifeCycleState stateRead() {
    calls++;
    return context.get_component_state(component);
  }

  /** What discovery reads first of every component. */
  @Benchmark
  public RTC.ComponentProfile profileRead() {
    calls++;
    return component.get_component_profile();
  }

  /** A heartbeat to the tree's observer, as the component's observer hub sends it: oneway. */
  @Benchmark
  public void notification() {
    calls++;
    observer.update_status(OpenRTM.StatusKind.HEARTBEAT, "");
  }

  @Setup(Level.Iteration)
  public void startIteration(BenchmarkParams benchmark) {
    calls = 0;
    ownCpuBefore = cpuNanos(ProcessHandle.current());
    peerCpuBefore = cpuNanos(peer(benchmark));
  }

  @TearDown(Level.Iteration)
  public void endIteration(BenchmarkParams benchmark, IterationParams iteration) throws IOException {
    if (iteration.getType() != IterationType.MEASUREMENT || calls == 0) return;
    long own = cpuNanos(ProcessHandle.current()) - ownCpuBefore;
    long peer = cpuNanos(peer(benchmark)) - peerCpuBefore;
    boolean notification = isNotification(benchmark);
    long coordinatorCpu = notification ? peer : own;
    long componentCpu = notification ? own : peer;
    String name = benchmark.getBenchmark().substring(benchmark.getBenchmark().lastIndexOf('.') + 1);
    String line = name + " " + (coordinatorCpu / (double) calls) + " " + (componentCpu / (double) calls) + " " + calls + "\n";
    Files.write(Paths.get(property("cpu")), line.getBytes(StandardCharsets.UTF_8), StandardOpenOption.CREATE, StandardOpenOption.APPEND);
  }

  private ProcessHandle peer(BenchmarkParams benchmark) {
    return isNotification(benchmark) ? coordinator : fixtures;
  }

  private static boolean isNotification(BenchmarkParams benchmark) {
    return benchmark.getBenchmark().endsWith(".notification");
  }

  private static long cpuNanos(ProcessHandle process) {
    return process.info().totalCpuDuration().map(Duration::toNanos).orElseThrow(() -> new IllegalStateException("no CPU time of process " + process.pid()));
  }

  private static String property(String name) {
    String value = System.getProperty("rtcoord.bench." + name);
    if (value == null) throw new IllegalStateException("rtcoord.bench." + name + " not set (MicroBench sets it)");
    return value;
  }
}
