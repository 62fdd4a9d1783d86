package org.rtcoord.bench

import java.util.concurrent.LinkedBlockingQueue

/**
 * The lines [process] prints on its standard output, as it prints them: read by a daemon thread named [name], so that a
 * child that fills its pipe never blocks, and taken from the queue with a deadline.
 */
internal fun linesOf(process: Process, name: String): LinkedBlockingQueue<String> =
    LinkedBlockingQueue<String>().also { lines ->
        Thread({ process.inputStream.bufferedReader().forEachLine { lines += it } }, name).apply {
            isDaemon = true
            start()
        }
    }
