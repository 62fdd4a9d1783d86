package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.check
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import kotlinx.serialization.json.JsonPrimitive
import org.rtcoord.PortData
import org.rtcoord.StructuredData
import org.rtcoord.TimedDouble
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TimedFloatSeq
import org.rtcoord.TimedLongSeq
import org.rtcoord.UnknownData
import org.rtcoord.cli.json.OneLineJson
import org.rtcoord.cli.json.SampleJson
import org.rtcoord.cli.json.dynamicJson
import org.rtcoord.datatypes.DataTypeName

/** `rtcoord print`: rtprint, working: the tree taps the out-port and prints each sample on a line. */
class PrintCommand : TreeCommand("print") {
    override fun help(context: Context): String =
        "Print the data an out-port sends, one line per sample: its time stamp, its type and its value: every " +
            "type of OpenRTM-aist's BasicDataType, ExtendedDataTypes and InterfaceDataTypes member by member (a long " +
            "sequence by its first values and its length; --json gives it whole), an unknown type as its name and the " +
            "raw bytes in hex. The tree taps the port as a connected in-port would; the tap's " +
            "connector (id rtcoord-tap-...) goes when the command ends. Runs until Ctrl-C, SIGTERM, --count samples or " +
            "--for has passed, then exits 0."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord print /localhost/host.host_cxt/laser0.rtc:laser" to "the laser's scans as they come",
            "rtcoord print laser0.rtc:laser --count 1 --json" to "one scan, as JSON",
            "rtcoord print gyro0.rtc:gyro --for 5s" to "five seconds of the gyro",
        )

    private val path by argument("PATH:PORT", help = "The out-port (component.rtc:port).")

    private val json by option("--json", help = "One JSON object per sample (as the global --json).").flag()

    private val count by
        option("--count", "-n", metavar = "N", help = "Stop after N samples.").int().check("must be positive") {
            it > 0
        }

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    override suspend fun execute() {
        val port = port(path)
        StopSignals().use { signals ->
            val samples = Channel<PortData>(Channel.UNLIMITED)
            port.tap { samples.trySend(it) }
            coroutineScope {
                val printing = launch {
                    var printed = 0
                    for (sample in samples) {
                        echo(if (json || session.json) OneLineJson.encodeToString(sample.toJson()) else sample.line())
                        if (++printed == count) break
                    }
                }
                val stopping = launch {
                    signals.await(duration)
                    printing.cancel()
                }
                printing.join()
                stopping.cancel()
            }
            // Closing the tree removes the tap before it returns; cancelling the tap would leave that to background
            // work the exit cuts short.
            tree.close()
        }
    }
}

/** A sample as one line: time stamp, type, value. */
internal fun PortData.line(): String = "${time ?: "-"}  ${typeLabel()}  ${valueText()}"

private fun PortData.typeLabel(): String =
    when (this) {
        is UnknownData -> typeName
        is StructuredData -> DataTypeName.simpleName(typeName)
        else -> javaClass.simpleName
    }

/** A structured sample's members but its time stamp, which the line and the JSON give apart. */
private val StructuredData.value: Map<String, Any?>
    get() = if (time != null) members - "tm" else members

private fun PortData.valueText(): String =
    when (this) {
        is UnknownData -> bytes.joinToString("") { "%02x".format(it) }
        is StructuredData -> MemberText.of(value)
        is TimedDoubleSeq -> data.joinToString(" ", "[", "]")
        is TimedFloatSeq -> data.joinToString(" ", "[", "]")
        is TimedLongSeq -> data.joinToString(" ", "[", "]")
        is TimedDouble -> data.toString()
        else -> toString().substringAfter("data=", "").removeSuffix(")").ifEmpty { toString() }
    }

/** A sample as JSON: time stamp, type and value. */
internal fun PortData.toJson(): SampleJson =
    SampleJson(
        time?.toString(),
        typeLabel(),
        when (this) {
            is UnknownData -> JsonPrimitive(bytes.joinToString("") { "%02x".format(it) })
            is StructuredData -> dynamicJson(value)
            is TimedDoubleSeq -> dynamicJson(data)
            is TimedFloatSeq -> dynamicJson(data)
            is TimedLongSeq -> dynamicJson(data)
            else -> JsonPrimitive(valueText())
        },
    )
