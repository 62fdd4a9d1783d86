package org.rtcoord.dsl;

import org.junit.jupiter.api.Test;
import org.rtcoord.ApiDump;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * The dsl's API has no data classes, by Kotlin's metadata, as core's has none (core's
 * {@code NoDataClassesTest}, whose scan it shares): a rule's or supervisor's status, a failed action, a
 * mode transition and a link are {@link org.rtcoord.ValueObject}s, which can gain fields compatibly.
 */
class DslNoDataClassesTest {
    @Test
    void theApiHasNoDataClass() {
        assertEquals(List.of(), ApiDump.dataClasses(ApiDump.publicClasses(Coordination.class)));
    }
}
