package org.rtcoord

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.CsvSource
import org.rtcoord.internal.ParameterConstraint

/** The `__constraints__` forms a value is checked against before a parameter is set. */
class ParameterConstraintTest {
    @ParameterizedTest(name = "{1} meets {0}")
    @CsvSource(
        delimiter = '|',
        value =
            [
                "0<x<10|5",
                "0<x<10|9.99",
                "0<=x<=10|0",
                "0<=x<=10|10",
                "x>=0|0",
                "x<1.5|-3",
                "-1<=x<=1|-1",
                "1e-3<x|0.5",
                "(slow,fast)|fast",
                "( slow , fast )|slow",
                "[0,1]|7",
                "{a:x<1}|9",
                "anything|at all",
            ],
    )
    fun `values that meet the constraint, or constraints of forms not checked`(constraint: String, value: String) {
        assertNull(ParameterConstraint.violation(constraint, value))
    }

    @ParameterizedTest(name = "{1} breaks {0}")
    @CsvSource(
        delimiter = '|',
        value =
            [
                "0<x<10|0|'0' is outside 0<x<10",
                "0<x<10|42|'42' is outside 0<x<10",
                "x>=0|-0.1|'-0.1' is outside x>=0",
                "0<=x<=10|10.5|'10.5' is outside 0<=x<=10",
                "x<1.5|1.5|'1.5' is outside x<1.5",
                "0<x<10|abc|'abc' is not a number (constraint 0<x<10)",
                "(slow,fast)|medium|'medium' is not one of (slow,fast)",
            ],
    )
    fun `values that break the constraint say how`(constraint: String, value: String, reason: String) {
        assertEquals(reason, ParameterConstraint.violation(constraint, value))
    }
}
