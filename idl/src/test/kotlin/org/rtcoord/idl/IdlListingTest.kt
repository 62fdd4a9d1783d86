package org.rtcoord.idl

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

class IdlListingTest {
    private val reference =
        IdlListing.parse(
            listOf(
                "RTC::PortService\tkind\tinterface",
                "RTC::PortService\toperation disconnect\tRTC::ReturnCode_t(in RTC::UniqueIdentifier)",
                "RTC::ExecutionKind\tenumerators\tPERIODIC, EVENT_DRIVEN, OTHER",
                "RTC::Unused\tkind\tstruct",
            )
        )

    @Test
    fun `identical declarations have no differences, whatever the reference adds`() {
        val ours =
            IdlListing.parse(
                listOf(
                    "RTC::PortService\tkind\tinterface",
                    "RTC::PortService\toperation disconnect\tRTC::ReturnCode_t(in RTC::UniqueIdentifier)",
                )
            )
        assertEquals(emptyList<String>(), ours.differencesFrom(reference))
    }

    @Test
    fun `a changed parameter type names the type and the operation`() {
        val ours =
            IdlListing.parse(
                listOf(
                    "RTC::PortService\tkind\tinterface",
                    "RTC::PortService\toperation disconnect\tRTC::ReturnCode_t(in long)",
                )
            )
        assertEquals(
            listOf(
                "RTC::PortService: operation disconnect: `RTC::ReturnCode_t(in long)` differs from the " +
                    "reference `RTC::ReturnCode_t(in RTC::UniqueIdentifier)`"
            ),
            ours.differencesFrom(reference),
        )
    }

    @Test
    fun `missing operations, reordered enumerators and unknown types are all reported`() {
        val ours =
            IdlListing.parse(
                listOf(
                    "RTC::PortService\tkind\tinterface",
                    "RTC::ExecutionKind\tenumerators\tEVENT_DRIVEN, PERIODIC, OTHER",
                    "RTC::Invented\tkind\tenum",
                    "OpenRTM::ComponentObserver\tkind\tinterface",
                )
            )
        assertEquals(
            listOf(
                "OpenRTM::ComponentObserver: not declared by the reference IDL",
                "RTC::ExecutionKind: enumerators: `EVENT_DRIVEN, PERIODIC, OTHER` differs from the reference " +
                    "`PERIODIC, EVENT_DRIVEN, OTHER`",
                "RTC::Invented: not declared by the reference IDL",
                "RTC::PortService: operation disconnect: missing here, reference has " +
                    "`RTC::ReturnCode_t(in RTC::UniqueIdentifier)`",
            ),
            ours.differencesFrom(reference),
        )
        val allowed = ours.differencesFrom(reference, extras = setOf("OpenRTM::ComponentObserver"))
        assertEquals(3, allowed.size)
        assertTrue(allowed.none { it.startsWith("OpenRTM::") })
    }
}
