package org.rtcoord.sim.explore

import java.nio.file.Files
import java.nio.file.Path
import java.util.Locale
import javax.xml.stream.XMLOutputFactory
import javax.xml.stream.XMLStreamWriter

/**
 * Writes an exploration as JUnit XML for CI: `TEST-NAME.explore.xml`, a test case per distinct failure (named by where
 * it fails, its failure holding the smallest schedule and the replay command, its output the first failing run's
 * timeline), or one passing test case saying how many runs found nothing.
 */
public object ExploreJUnit {
    private val factory: XMLOutputFactory = XMLOutputFactory.newFactory()

    /** Writes [report] into [directory] (created if needed); returns the file written. */
    @JvmStatic
    public fun write(report: ExploreReport, directory: Path): Path {
        Files.createDirectories(directory)
        val suite = report.file.name.replace('/', '.') + ".explore"
        val file = directory.resolve("TEST-$suite.xml")
        Files.newBufferedWriter(file).use { out ->
            val xml = factory.createXMLStreamWriter(out)
            xml.writeStartDocument("UTF-8", "1.0")
            xml.writeCharacters("\n")
            xml.writeStartElement("testsuite")
            xml.writeAttribute("name", suite)
            xml.writeAttribute("tests", report.failures.size.coerceAtLeast(1).toString())
            xml.writeAttribute("failures", report.failures.size.toString())
            xml.writeAttribute("errors", "0")
            xml.writeAttribute("skipped", "0")
            xml.writeAttribute("time", String.format(Locale.ROOT, "%.3f", report.elapsed.inWholeMilliseconds / 1000.0))
            if (report.failures.isEmpty()) {
                testcase(xml, suite, "no failure in ${report.runs} runs of seed ${report.seed}") {}
            }
            for (found in report.failures) {
                testcase(xml, suite, found.failure.at) {
                    xml.writeCharacters("\n    ")
                    xml.writeStartElement("failure")
                    xml.writeAttribute("message", clean(found.failure.toString()))
                    xml.writeAttribute("type", "explored")
                    val lines =
                        listOf(found.failure.toString()) +
                            found.failure.details.map { "  $it" } +
                            listOf(
                                "scenario: ${found.scenario}",
                                "failed in ${found.occurrences} run(s), first ${found.firstRun}: ${found.drawn}",
                                "smallest schedule: ${found.smallest}",
                                "replay: ${found.replay}",
                            ) +
                            listOfNotNull(found.test?.let { "regression test: $it" })
                    xml.writeCharacters(clean(lines.joinToString("\n")))
                    xml.writeEndElement()
                    if (found.timeline.isNotEmpty()) {
                        xml.writeCharacters("\n    ")
                        xml.writeStartElement("system-out")
                        xml.writeCharacters(clean(found.timeline.joinToString("\n")))
                        xml.writeEndElement()
                    }
                }
            }
            xml.writeCharacters("\n")
            xml.writeEndElement()
            xml.writeCharacters("\n")
            xml.writeEndDocument()
            xml.close()
        }
        return file
    }

    private inline fun testcase(xml: XMLStreamWriter, suite: String, name: String, body: () -> Unit) {
        xml.writeCharacters("\n  ")
        xml.writeStartElement("testcase")
        xml.writeAttribute("classname", suite)
        xml.writeAttribute("name", name)
        body()
        xml.writeCharacters("\n  ")
        xml.writeEndElement()
    }

    /** [text] without the control characters XML 1.0 cannot hold. */
    private fun clean(text: String): String = text.filter { it == '\n' || it == '\t' || it == '\r' || it >= ' ' }
}
