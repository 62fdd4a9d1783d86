package org.rtcoord.internal

/**
 * Whether nothing answers for [target]: its ORB is gone (refused), or its ORB no longer has it. An object that answers,
 * or whose fate the call cannot tell (a timeout), is not gone. Blocking: call it through [Remote].
 */
internal fun isGone(target: org.omg.CORBA.Object): Boolean =
    try {
        target._non_existent()
    } catch (e: org.omg.CORBA.OBJECT_NOT_EXIST) {
        true
    } catch (e: org.omg.CORBA.OBJ_ADAPTER) {
        true
    } catch (e: org.omg.CORBA.TRANSIENT) {
        true
    }
