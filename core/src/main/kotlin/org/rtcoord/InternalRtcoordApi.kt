package org.rtcoord

/**
 * Marks a declaration that is public only so that rtcoord's own modules (the dsl) can share it with core; it is no API,
 * and may change or go without notice. Using it needs `@OptIn(InternalRtcoordApi::class)`.
 */
@RequiresOptIn(
    message = "This is rtcoord's internal API, shared between its own modules; it may change without notice."
)
@Retention(AnnotationRetention.BINARY)
@Target(AnnotationTarget.CLASS, AnnotationTarget.FUNCTION, AnnotationTarget.CONSTRUCTOR)
public annotation class InternalRtcoordApi
