package org.rtcoord.sim.test

/** The lines a failed scenario is reported with: each failure, what explains it, then the scenario's timeline. */
public object TestReport {
    /** How many of a timeline's last entries [failures] shows. */
    private const val TIMELINE = 60

    /** Each failure of [result] as `file:line:col: what`, each of its details indented under it. */
    @JvmStatic
    public fun failures(result: TestResult): List<String> =
        result.failures.flatMap { failure -> listOf(failure.toString()) + failure.details.map { "  $it" } }

    /** [result]'s timeline as a failure shows it: its last entries, with times from the scenario's start. */
    @JvmStatic
    public fun timeline(result: TestResult): List<String> {
        val entries = result.timeline
        if (entries.isEmpty()) return emptyList()
        val shown = entries.takeLast(TIMELINE)
        val header =
            "timeline (seconds from the coordinator's start)" +
                if (shown.size < entries.size) ", the last ${shown.size} of ${entries.size} entries:" else ":"
        return listOf(header) + shown.map(TimelineEntry::toString)
    }
}
