package org.rtcoord.runtime

import org.omg.CORBA.portable.ObjectImpl

/**
 * What JacORB's `_is_equivalent` compares (type id and object key), read from the reference as it is. `_is_equivalent`
 * stringifies and re-parses both references on every call, which made each lookup of a caller-supplied reference cost
 * more than the request carrying it.
 */
internal fun org.omg.CORBA.Object.identity(): String =
    ((this as ObjectImpl)._get_delegate() as org.jacorb.orb.Delegate).idString
