@file:JvmName("BenchMain")

package org.rtcoord.bench

import kotlin.system.exitProcess
import kotlinx.coroutines.runBlocking

/**
 * Runs the benchmarks the arguments choose (see `scripts/bench --help`) and prints one table on stdout; progress goes
 * to stderr. The explicit exit matters: JacORB leaves non-daemon threads behind.
 */
fun main(args: Array<String>) {
    if ("--help" in args) {
        println(BenchOptions.USAGE)
        exitProcess(0)
    }
    val options =
        try {
            BenchOptions.parse(args.toList())
        } catch (e: IllegalArgumentException) {
            System.err.println("bench: ${e.message}")
            System.err.println(BenchOptions.USAGE)
            exitProcess(2)
        }
    val report = runBlocking { Bench(options, Installation.find()).run() }
    report.print(System.out)
    exitProcess(0)
}
