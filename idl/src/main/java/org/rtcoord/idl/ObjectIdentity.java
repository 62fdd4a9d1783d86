package org.rtcoord.idl;

import org.omg.CORBA.portable.ObjectImpl;

/**
 * Which object a reference names, as a string two references share exactly when JacORB's {@code
 * _is_equivalent} holds: the type id and the object key. {@code _is_equivalent} stringifies and
 * parses both references again on every call; read from the reference as it is, the identity costs a
 * small fraction of that, and can key a map. A tree relisting a thousand components each second made
 * that comparison a thousand times a second (bench/README.md).
 */
public final class ObjectIdentity {
  private ObjectIdentity() {}

  /**
   * The identity of {@code reference}; for a reference of another ORB than JacORB, its stringified
   * IOR.
   */
  public static String of(org.omg.CORBA.Object reference) {
    org.omg.CORBA.portable.Delegate delegate = ((ObjectImpl) reference)._get_delegate();
    if (delegate instanceof org.jacorb.orb.Delegate) {
      return ((org.jacorb.orb.Delegate) delegate).getIDString();
    }
    return delegate.orb(reference).object_to_string(reference);
  }

  /** Whether {@code a} and {@code b} name the same object, as {@link #of} tells. */
  public static boolean same(org.omg.CORBA.Object a, org.omg.CORBA.Object b) {
    return a == b || of(a).equals(of(b));
  }
}
