package org.rtcoord.profile

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import org.jspecify.annotations.Nullable
import org.rtcoord.LifeCycle
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.profile.internal.SystemCapture
import org.rtcoord.profile.internal.SystemCheck
import org.rtcoord.profile.internal.SystemOrdering
import org.rtcoord.profile.internal.SystemRestore
import org.rtcoord.profile.internal.SystemTeardown

/**
 * Whole-system operations on a live [tree] with RTSProfiles, as RTSystemEditor and rtshell's rtcryo, rtresurrect,
 * rtcheck, rtstart, rtstop and rtteardown do: each checks what it can before it changes anything, and each remote call
 * has the tree's deadline. Kotlin's: its operations suspend, and Java calls them through
 * [org.rtcoord.java.JavaSystemProfiles].
 */
public class SystemProfiles(private val tree: RtcTree) {
    /**
     * The running system below [below] as a profile: components (only those with connections when [onlyConnected], as
     * rtcryo), their ports, configuration sets and active set, owned execution contexts and rates, and the connections
     * among them with their properties.
     */
    @JvmSynthetic
    public suspend fun save(
        below: RtcPath = RtcPath("/"),
        onlyConnected: Boolean = false,
        systemId: String = "RTSystem:rtcoord:RTSystem:0",
        abstract: String = "",
    ): RtsProfile = SystemCapture(tree).capture(below, onlyConnected, systemId, abstract)

    /**
     * Restores [profile] onto the running system: components are found by `pathUri`; connections the system lacks are
     * made with their properties (identical ones kept); configuration sets are written and the active set activated;
     * execution context rates set. Everything is checked first: a missing required component, a missing port,
     * incompatible ports, a connection that exists with other properties is a [ProfileRefusedException] before anything
     * changes. Missing optional components are reported. Restoring again changes nothing.
     *
     * A value the restore would write outside the constraint its component declares (`__constraints__`) is written, as
     * OpenRTM-aist and rtresurrect write it, and named in [RestoreReport.warnings]; with [strict] it refuses the
     * restore instead. A value the component holds is not written, so a profile saved from a system always restores
     * onto it unchanged, even where the system holds values outside their constraints (OpenRTM-aist's own ConfigSample
     * does).
     *
     * With [createMissing], missing components (required or not) are first created through a manager: the one bound in
     * the component's naming context or nearest above it (a master before a slave, which loads the type's module if it
     * must), by the type in the component id and the profile's instance name. No manager for one of them refuses the
     * restore before anything is created; a restore refused after creating deletes what it created.
     */
    @JvmSynthetic
    public suspend fun restore(
        profile: RtsProfile,
        createMissing: Boolean = false,
        strict: Boolean = false,
    ): RestoreReport = SystemRestore(tree).restore(profile, createMissing, strict)

    /**
     * How the live system differs from [profile]: missing components, states other than [state] (not compared when
     * null), missing or different connections, configuration and rates.
     */
    @JvmSynthetic
    public suspend fun check(
        profile: RtsProfile,
        state: @Nullable LifeCycle? = LifeCycle.ACTIVE,
    ): List<ProfileDifference> = SystemCheck(tree).check(profile, state)

    /** The steps [action] takes for [profile], in order; changes nothing. */
    public fun plan(profile: RtsProfile, action: OrderedAction): List<PlannedStep> =
        SystemOrdering(tree).plan(profile, action)

    /**
     * Runs [action] in the profile's order: steps of a higher sequence wait for those of lower ones, `WaitTime` and
     * `Preceding` (SYNC or ASYNC, with timeout) conditions are honoured, and each step has [stepDeadline] beyond its
     * condition's own time. Returns every step's outcome.
     */
    @JvmSynthetic
    public suspend fun run(
        profile: RtsProfile,
        action: OrderedAction,
        stepDeadline: Duration = 10.seconds,
    ): List<StepOutcome> = SystemOrdering(tree).run(profile, action, stepDeadline)

    /** Removes the connections [profile] names; returns what was removed. */
    @JvmSynthetic
    public suspend fun teardown(profile: RtsProfile): List<String> = SystemTeardown(tree).teardown(profile)
}
