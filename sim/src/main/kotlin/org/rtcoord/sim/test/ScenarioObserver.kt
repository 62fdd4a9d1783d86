package org.rtcoord.sim.test

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.ComparableTimeMark
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.rtcoord.RtcEvent
import org.rtcoord.SystemSnapshot

/**
 * The one owner of what happened in a scenario: takes the system's events, the coordinator's log lines and modes, the
 * faults injected and the steps' outcomes, from any thread, and handles them one at a time in the order they came, in
 * [run]: records each in the timeline, applies it to the [model], and checks every invariant begun so far against the
 * model just after it. The first invariant that does not hold is handed to [broke], with the entry that broke it and
 * its time. [changes] counts the entries, for expectations to read their condition again on each.
 */
internal class ScenarioObserver(
    private val model: SystemModel,
    private val source: TestSource,
    private val broke: (TestFailure) -> Unit,
    /** The scenario's clock, which the timeline's times are read on. */
    private val clock: ScenarioClock,
) {
    private sealed class Input {
        class Started(val snapshot: SystemSnapshot) : Input()

        class Happened(
            val mark: ComparableTimeMark,
            val kind: TimelineEntry.Kind,
            val text: String,
            val event: RtcEvent? = null,
            val mode: Pair<String, String?>? = null,
        ) : Input()

        class Begin(val invariant: TestStep.Invariant) : Input()
    }

    private class Entry(val mark: ComparableTimeMark, val kind: TimelineEntry.Kind, val text: String)

    private val inputs = Channel<Input>(Channel.UNLIMITED)
    private val entries = CopyOnWriteArrayList<Entry>()
    private val invariants = mutableListOf<TestStep.Invariant>()
    private val count = MutableStateFlow(0L)

    /** When the scenario started (the coordinator's start); set once it has. */
    @Volatile var origin: ComparableTimeMark? = null

    /** How many entries have been handled: changes with each. */
    val changes: StateFlow<Long> = count.asStateFlow()

    /** The model as the tree's first look at the system shows it; before any event. */
    fun started(snapshot: SystemSnapshot) {
        inputs.trySend(Input.Started(snapshot))
    }

    fun event(event: RtcEvent) = happened(TimelineEntry.Kind.EVENT, EventLines.of(event), event = event)

    fun log(line: String) = happened(TimelineEntry.Kind.LOG, line)

    fun fault(what: String) = happened(TimelineEntry.Kind.FAULT, what)

    fun step(what: String) = happened(TimelineEntry.Kind.STEP, what)

    fun mode(machine: String, mode: String?) =
        happened(TimelineEntry.Kind.MODE, "$machine: ${mode ?: "no mode"}", mode = machine to mode)

    /** Checks [invariant] from now on, and first against the model as it is once what came before is handled. */
    fun begin(invariant: TestStep.Invariant) {
        inputs.trySend(Input.Begin(invariant))
    }

    private fun happened(
        kind: TimelineEntry.Kind,
        text: String,
        event: RtcEvent? = null,
        mode: Pair<String, String?>? = null,
    ) {
        inputs.trySend(Input.Happened(clock.markNow(), kind, text, event, mode))
    }

    /** Handles what comes, in order, until [close] and what came before it is handled. */
    suspend fun run() {
        for (input in inputs) {
            when (input) {
                is Input.Started -> model.start(input.snapshot)
                is Input.Begin -> {
                    invariants += input.invariant
                    check(listOf(input.invariant), null)
                }
                is Input.Happened -> {
                    entries += Entry(input.mark, input.kind, input.text)
                    input.event?.let(model::apply)
                    input.mode?.let { (machine, mode) -> model.mode(machine, mode) }
                    if (input.kind == TimelineEntry.Kind.LOG) model.log(input.text)
                    check(invariants.toList(), input)
                    count.value++
                }
            }
        }
    }

    /** Takes nothing more: [run] ends once what came before is handled. */
    fun close() {
        inputs.close()
    }

    /** The timeline so far, times from [origin] (from the first entry before the scenario started). */
    fun timeline(): List<TimelineEntry> {
        val all = entries.toList()
        val zero = origin ?: all.firstOrNull()?.mark ?: return emptyList()
        return all.map { TimelineEntry(it.mark - zero, it.kind, it.text) }
    }

    /**
     * Checks [checked] against the model just after [cause] (null: as it is when they begin); the first that does not
     * hold ends the checking of all.
     */
    private suspend fun check(checked: List<TestStep.Invariant>, cause: Input.Happened?) {
        for (invariant in checked) {
            val observation = RecordedObservation(model)
            val failure =
                try {
                    if (invariant.keptBy(invariant.condition(observation))) continue
                    null
                } catch (e: CancellationException) {
                    throw e
                } catch (e: Exception) {
                    e
                }
            val time =
                (cause?.mark ?: clock.markNow()).let { mark ->
                    origin?.let { TimelineEntry.seconds(mark - it) }
                }
            val whenBroken =
                if (cause == null) "when it began${time?.let { " at $it" }.orEmpty()}"
                else "at $time, on ${cause.kind.name.lowercase()}: ${cause.text}"
            val what = "${invariant.word} { ${source.condition(invariant)} }"
            val message =
                if (failure == null) "$what broke $whenBroken"
                else "$what could not be read $whenBroken: ${failure.message ?: failure.javaClass.simpleName}"
            invariants.clear()
            broke(TestFailure(source.at(invariant), message, observation.readings.map(Reading::toString)))
            return
        }
    }
}
