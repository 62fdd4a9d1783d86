package org.rtcoord.idl;

import org.omg.CORBA.Any;
import org.omg.CORBA.ORB;
import org.omg.CORBA.TypeCode;
import org.omg.CORBA.portable.InputStream;
import org.omg.CORBA.portable.OutputStream;

/**
 * Marshals plain {@code Object} references (the IDL type {@code Object}) for generated stubs.
 *
 * <p>The IDL-to-Java mapping expects {@code org.omg.CORBA.ObjectHelper}, which jacorb-omgapi does not
 * provide; the build points the generated code here instead, so the CORBA packages stay unsplit.
 */
public final class ObjectHelper {
  private static final String ID = "IDL:omg.org/CORBA/Object:1.0";

  private ObjectHelper() {}

  /** The repository ID of {@code Object}. */
  public static String id() {
    return ID;
  }

  /** The type code of {@code Object}. */
  public static TypeCode type() {
    return ORB.init().create_interface_tc(ID, "Object");
  }

  /** Stores a reference in an {@code any}. */
  public static void insert(Any any, org.omg.CORBA.Object value) {
    any.insert_Object(value);
  }

  /** Reads a reference out of an {@code any}. */
  public static org.omg.CORBA.Object extract(Any any) {
    return any.extract_Object();
  }

  /** Reads a reference from a CDR stream. */
  public static org.omg.CORBA.Object read(InputStream in) {
    return in.read_Object();
  }

  /** Writes a reference to a CDR stream. */
  public static void write(OutputStream out, org.omg.CORBA.Object value) {
    out.write_Object(value);
  }
}
