package org.rtcoord.sim.test

import java.io.Writer
import java.nio.file.Files
import java.nio.file.Path
import java.util.Locale
import javax.xml.stream.XMLOutputFactory
import javax.xml.stream.XMLStreamWriter
import kotlin.time.Duration

/**
 * Writes test results as JUnit XML, the form CI servers (Jenkins, GitLab) read: one `TEST-NAME.xml` per test file, NAME
 * its unique [TestFile.name] with `/` as `.`, holding a test case per scenario; the test case's class name is that
 * NAME, so that files of one name in two directories stay apart. A failed scenario's failure holds its failures with
 * what explains them, and its output the scenario's timeline and the coordinator's log.
 */
public object JUnitXml {
    private val factory: XMLOutputFactory = XMLOutputFactory.newFactory()

    /** Writes one file per test file of [results] into [directory] (created if needed); returns the files written. */
    @JvmStatic
    public fun write(results: List<TestResult>, directory: Path): List<Path> {
        Files.createDirectories(directory)
        return results
            .groupBy { it.file.name }
            .map { (name, scenarios) ->
                val file = directory.resolve("TEST-${className(name)}.xml")
                Files.newBufferedWriter(file).use { writer -> write(writer, name, scenarios) }
                file
            }
    }

    private fun write(out: Writer, name: String, scenarios: List<TestResult>) {
        val xml = factory.createXMLStreamWriter(out)
        xml.writeStartDocument("UTF-8", "1.0")
        xml.writeCharacters("\n")
        xml.writeStartElement("testsuite")
        xml.writeAttribute("name", className(name))
        xml.writeAttribute("tests", scenarios.size.toString())
        xml.writeAttribute("failures", scenarios.count { !it.passed }.toString())
        xml.writeAttribute("errors", "0")
        xml.writeAttribute("skipped", "0")
        xml.writeAttribute("time", seconds(scenarios.fold(Duration.ZERO) { sum, it -> sum + it.duration }))
        for (scenario in scenarios) testcase(xml, scenario)
        xml.writeCharacters("\n")
        xml.writeEndElement()
        xml.writeCharacters("\n")
        xml.writeEndDocument()
        xml.close()
    }

    private fun testcase(xml: XMLStreamWriter, result: TestResult) {
        xml.writeCharacters("\n  ")
        xml.writeStartElement("testcase")
        xml.writeAttribute("classname", className(result.file.name))
        xml.writeAttribute("name", result.scenario)
        xml.writeAttribute("file", result.file.path.toString())
        xml.writeAttribute("time", seconds(result.duration))
        if (!result.passed) {
            xml.writeCharacters("\n    ")
            xml.writeStartElement("failure")
            xml.writeAttribute("message", clean(result.failures.first().toString()))
            xml.writeAttribute("type", "expectation")
            xml.writeCharacters(
                clean(
                    result.failures.joinToString("\n") { failure ->
                        (listOf(failure.toString()) + failure.details.map { "  $it" }).joinToString("\n")
                    }
                )
            )
            xml.writeEndElement()
        }
        val output = result.timeline.joinToString("\n")
        if (output.isNotEmpty()) {
            xml.writeCharacters("\n    ")
            xml.writeStartElement("system-out")
            xml.writeCharacters(clean(output))
            xml.writeEndElement()
        }
        xml.writeCharacters("\n  ")
        xml.writeEndElement()
    }

    /** Jenkins and GitLab read a class name's dots as packages: `a/transient` is `a.transient`. */
    private fun className(name: String): String = name.replace('/', '.')

    private fun seconds(duration: Duration): String =
        String.format(Locale.ROOT, "%.3f", duration.inWholeMilliseconds / 1000.0)

    /** [text] without the control characters XML 1.0 cannot hold, which a log line may carry. */
    private fun clean(text: String): String = text.filter { it == '\n' || it == '\t' || it == '\r' || it >= ' ' }
}
