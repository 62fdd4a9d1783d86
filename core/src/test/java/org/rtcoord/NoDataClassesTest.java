package org.rtcoord;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Core's API has no data classes, by Kotlin's metadata ({@link ApiDump#dataClasses}): their
 * {@code componentN} and {@code copy} tie compiled callers to the list of fields, so that adding one
 * breaks them. Snapshots, events, samples and profiles are {@link ValueObject}s instead, which keep
 * {@code equals}, {@code hashCode} and {@code toString}.
 */
class NoDataClassesTest {
    @Test
    void theApiHasNoDataClass() {
        assertEquals(List.of(), ApiDump.dataClasses(ApiDump.publicClasses(RtcTree.class)));
    }
}
