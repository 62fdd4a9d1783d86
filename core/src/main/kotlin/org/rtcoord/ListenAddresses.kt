@file:JvmName("ListenAddresses")

package org.rtcoord

import org.rtcoord.internal.ListenAddress

/**
 * Why a tree's ORB could not listen on [address] ([TreeConfig.listenAddress]), or null when it can: one of this host's
 * addresses, or `0.0.0.0`. What a tool's settings check before they make a [TreeConfig], which refuses such an address.
 * Java: `ListenAddresses.listenAddressProblem(address)`.
 */
public fun listenAddressProblem(address: String): String? = ListenAddress.problem(address)
