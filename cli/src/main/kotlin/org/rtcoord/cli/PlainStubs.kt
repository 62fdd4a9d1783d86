package org.rtcoord.cli

import java.io.NotSerializableException
import java.io.ObjectInputStream
import java.io.ObjectOutputStream
import java.rmi.RemoteException
import javax.rmi.CORBA.Stub
import javax.rmi.CORBA.StubDelegate
import org.omg.CORBA.ORB

/**
 * How the command's untyped object references (JacORB makes them `javax.rmi.CORBA.Stub`s) hash, compare and print: as
 * the plain CORBA objects they are, through their ORB delegates. The RMI-IIOP default starts java.util.logging when the
 * first reference is made, and that start searches every jar of the class path (the Kotlin compiler's among them): tens
 * of milliseconds on every command's first call.
 */
class PlainStubs : StubDelegate {
    override fun hashCode(self: Stub): Int = self._get_delegate().hashCode(self)

    override fun equals(self: Stub, obj: Any?): Boolean = self._get_delegate().equals(self, obj)

    override fun toString(self: Stub): String = self._get_delegate().toString(self)

    override fun connect(self: Stub, orb: ORB): Unit = throw RemoteException("rtcoord does not export RMI objects")

    override fun readObject(self: Stub, stream: ObjectInputStream): Unit =
        throw NotSerializableException(self.javaClass.name)

    override fun writeObject(self: Stub, stream: ObjectOutputStream): Unit =
        throw NotSerializableException(self.javaClass.name)
}
