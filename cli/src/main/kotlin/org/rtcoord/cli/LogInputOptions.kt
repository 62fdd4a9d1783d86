package org.rtcoord.cli

import com.github.ajalt.clikt.parameters.groups.OptionGroup
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.LogInput
import org.rtcoord.RtcTree

/** Where the command receives the components' log records: a Fluentd forward input. */
class LogInputOptions : OptionGroup("Log records") {
    private val address: String? by
        option(
            "--logs-listen",
            metavar = "ADDRESS:PORT",
            help =
                "Receive the components' log records on ADDRESS:PORT, a Fluentd forward input (OpenRTM-aist's " +
                    "FluentLogger and fluentbit_stream send to 127.0.0.1:24224 by default).",
        )

    private val sharedKey: String? by
        option(
            "--logs-key",
            metavar = "KEY",
            envvar = "RTCOORD_LOGS_KEY",
            help = "Require Fluentd's shared-key handshake with KEY (set it for any address beyond loopback).",
        )

    /** Starts [tree]'s log input where `--logs-listen` says, else on [orElse]; none when both are null. */
    fun start(tree: RtcTree, orElse: String? = null): LogInput? =
        (address ?: orElse)?.let { tree.listenForLogs(it, sharedKey) }
}
