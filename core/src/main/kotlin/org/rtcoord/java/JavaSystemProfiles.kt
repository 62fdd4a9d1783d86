package org.rtcoord.java

import java.time.Duration
import java.util.concurrent.CompletableFuture
import kotlin.time.toKotlinDuration
import org.jspecify.annotations.Nullable
import org.rtcoord.LifeCycle
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.internal.JavaCalls
import org.rtcoord.profile.OrderedAction
import org.rtcoord.profile.ProfileDifference
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.profile.RestoreReport
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.StepOutcome
import org.rtcoord.profile.SystemProfiles

/** [SystemProfiles] for Java callers: each operation blocking, and as a [CompletableFuture] (`...Async`). */
public class JavaSystemProfiles(
    /** The tree whose system is saved, restored, checked and run. */
    tree: JavaTree
) {
    private val profiles = SystemProfiles(tree.tree)
    private val calls = JavaCalls(tree.tree.core.scope)

    /**
     * The running system below [below] as a profile (see [SystemProfiles.save]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun save(below: String = "/", onlyConnected: Boolean = false): RtsProfile = calls.await {
        profiles.save(RtcPath(below), onlyConnected)
    }

    /** [save], when done; it fails with what [save] throws. */
    @JvmOverloads
    public fun saveAsync(below: String = "/", onlyConnected: Boolean = false): CompletableFuture<RtsProfile> =
        calls.future {
            profiles.save(RtcPath(below), onlyConnected)
        }

    /**
     * Restores [profile] onto the running system (see [SystemProfiles.restore]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws ProfileRefusedException when the profile cannot be applied as a whole (a required component or port
     *   missing, ports that do not fit, a connection with other properties); nothing was changed.
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, ProfileRefusedException::class, InterruptedException::class)
    public fun restore(profile: RtsProfile, createMissing: Boolean = false, strict: Boolean = false): RestoreReport =
        calls.await {
            profiles.restore(profile, createMissing, strict)
        }

    /** [restore], when done; it fails with what [restore] throws. */
    @JvmOverloads
    public fun restoreAsync(
        profile: RtsProfile,
        createMissing: Boolean = false,
        strict: Boolean = false,
    ): CompletableFuture<RestoreReport> = calls.future { profiles.restore(profile, createMissing, strict) }

    /**
     * How the live system differs from [profile], components compared against [state] when not null (see
     * [SystemProfiles.check]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, InterruptedException::class)
    public fun check(profile: RtsProfile, state: @Nullable LifeCycle? = LifeCycle.ACTIVE): List<ProfileDifference> =
        calls.await {
            profiles.check(profile, state)
        }

    /** [check], when done; it fails with what [check] throws. */
    @JvmOverloads
    public fun checkAsync(
        profile: RtsProfile,
        state: @Nullable LifeCycle? = LifeCycle.ACTIVE,
    ): CompletableFuture<List<ProfileDifference>> = calls.future { profiles.check(profile, state) }

    /**
     * Runs [action] in the profile's order, each step within [stepDeadline] beyond its condition (see
     * [SystemProfiles.run]).
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws ProfileRefusedException when the profile's order names a component the profile does not have; nothing was
     *   done.
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @JvmOverloads
    @Throws(RtcException::class, ProfileRefusedException::class, InterruptedException::class)
    public fun run(
        profile: RtsProfile,
        action: OrderedAction,
        stepDeadline: Duration = Duration.ofSeconds(10),
    ): List<StepOutcome> = calls.await { profiles.run(profile, action, stepDeadline.toKotlinDuration()) }

    /** [run], when done; it fails with what [run] throws. */
    @JvmOverloads
    public fun runAsync(
        profile: RtsProfile,
        action: OrderedAction,
        stepDeadline: Duration = Duration.ofSeconds(10),
    ): CompletableFuture<List<StepOutcome>> = calls.future {
        profiles.run(profile, action, stepDeadline.toKotlinDuration())
    }

    /**
     * Removes the connections [profile] names; returns what was removed.
     *
     * @throws RtcException naming what failed and why: one of its subclasses (`NotFoundException`,
     *   `UnreachableException`, `TimedOutException`, `OperationFailedException`, ...).
     * @throws InterruptedException if the calling thread is interrupted while it waits; the operation is cancelled.
     * @throws org.rtcoord.ClosedException once the tree is closed.
     */
    @Throws(RtcException::class, InterruptedException::class)
    public fun teardown(profile: RtsProfile): List<String> = calls.await { profiles.teardown(profile) }

    /** [teardown], when done; it fails with what [teardown] throws. */
    public fun teardownAsync(profile: RtsProfile): CompletableFuture<List<String>> = calls.future {
        profiles.teardown(profile)
    }
}
