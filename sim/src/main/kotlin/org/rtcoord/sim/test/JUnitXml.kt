package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import java.util.Locale

/** Writes test results as JUnit XML, the form CI servers read: one `TEST-NAME.xml` per test file. */
public object JUnitXml {
    /** Writes one file per result into [directory] (created if needed); returns the files written. */
    @JvmStatic
    public fun write(results: List<TestResult>, directory: Path): List<Path> {
        Files.createDirectories(directory)
        return results.map { result ->
            val seconds = String.format(Locale.ROOT, "%.3f", result.duration.inWholeMilliseconds / 1000.0)
            val failure = if (result.passed) "" else {
                val message = escape(result.failures.first())
                "\n    <failure message=\"$message\" type=\"expectation\">${escape(result.failures.joinToString("\n"))}</failure>"
            }
            val output = if (result.log.isEmpty()) "" else "\n    <system-out>${escape(result.log.joinToString("\n"))}</system-out>"
            val xml = """
                |<?xml version="1.0" encoding="UTF-8"?>
                |<testsuite name="${escape(result.name)}" tests="1" failures="${if (result.passed) 0 else 1}" errors="0" skipped="0" time="$seconds">
                |  <testcase classname="rtcoord.test" name="${escape(result.name)}" file="${escape(result.file.toString())}" time="$seconds">$failure$output
                |  </testcase>
                |</testsuite>
                |""".trimMargin()
            directory.resolve("TEST-${result.name}.xml").also { Files.writeString(it, xml) }
        }
    }

    private fun escape(text: String): String = buildString {
        for (c in text) {
            when (c) {
                '&' -> append("&amp;")
                '<' -> append("&lt;")
                '>' -> append("&gt;")
                '"' -> append("&quot;")
                '\n' -> append("&#10;")
                else -> if (c < ' ' && c != '\t') append(' ') else append(c)
            }
        }
    }
}
