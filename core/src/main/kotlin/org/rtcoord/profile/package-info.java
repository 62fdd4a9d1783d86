/**
 * Types are non-null unless marked {@code @Nullable}, for Java tools' null analysis (JSpecify): the
 * Kotlin signatures' nullability, written where Java reads it.
 */
@NullMarked
package org.rtcoord.profile;

import org.jspecify.annotations.NullMarked;
