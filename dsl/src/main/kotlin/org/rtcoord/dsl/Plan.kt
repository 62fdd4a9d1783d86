package org.rtcoord.dsl

import java.nio.file.Path
import org.rtcoord.EventOptions
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles

/**
 * What a script declared, frozen when a coordinator is made: rules, timers, supervisors and mode machines, with plain
 * selectors for what they name. It holds nothing of a run, so one plan can be started any number of times, one run
 * after another or at once on different trees.
 *
 * @property directory what the script's relative file names (profiles) are relative to.
 */
internal class Plan(
    val rules: List<Rule<*>>,
    val dataRules: List<DataRule>,
    val timers: List<Timer>,
    /** What runs when a run stops, before it stops watching. */
    val stopActions: List<suspend Reaction.() -> Unit>,
    val supervisions: List<Supervision>,
    val machines: List<ModeMachine>,
    val nameServers: List<String>,
    /** The managers the script named as it was evaluated (those its handlers name are watched once used). */
    val managers: List<String>,
    val watching: EventOptions,
    val directory: Path,
)

/** The RTSProfile in [file], relative to this directory; read anew at each call. */
internal fun Path.profile(file: String): RtsProfile = RtsProfiles.read(resolve(file))
