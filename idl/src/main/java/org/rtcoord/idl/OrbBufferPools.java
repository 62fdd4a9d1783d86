package org.rtcoord.idl;

import org.jacorb.config.Configuration;
import org.jacorb.orb.BufferManager;
import org.jacorb.orb.BufferManagerFactory;
import org.jacorb.orb.IBufferManager;

/**
 * Buffer pools of each ORB's own (JacORB's {@code jacorb.buffermanager.factory}, set by {@link OrbRecipe}).
 *
 * <p>JacORB's default gives every ORB of a JVM one shared pool, and an ORB's {@code destroy} empties it
 * without taking the lock its readers take. Another ORB taking a buffer at that moment fails in its
 * message receptor (an {@code IndexOutOfBoundsException}), which closes the connection: the call waiting
 * on it fails with {@code COMM_FAILURE}. Trees, simulated systems and test runs share a JVM and end at
 * different times, so each ORB keeps its pools to itself.
 */
public final class OrbBufferPools implements BufferManagerFactory {
  /** Made by JacORB from the class name. */
  public OrbBufferPools() {}

  @Override
  public IBufferManager newSingletonBufferManager(Configuration configuration) {
    return new BufferManager(configuration);
  }

  @Override
  public IBufferManager newBufferManager(IBufferManager shared, Configuration configuration) {
    return new BufferManager(configuration);
  }
}
