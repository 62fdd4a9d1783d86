package org.rtcoord.dsl.script

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

/**
 * The names a script's text passes to the DSL, as `check` reads them: where, of what kind, and which it cannot know.
 */
class WrittenNamesTest {
    private fun read(text: String) =
        WrittenNames.read(text).map { "${it.position} ${it.kind} ${it.name ?: "(${it.expression})"}" }

    @Test
    fun `names in rules and handlers, with the column of their opening quote`() {
        val text =
            """
            on(component("laser0.rtc")).state(ERROR) {
                component("lazer0").reset()
                connect("odometry0.rtc:odo", component("odo_localise0.rtc").port("odo"), mapOf("a" to "b"))
                manager().create("odo_localise")
            }
            """
                .trimIndent()
        assertEquals(
            listOf(
                "1:14 COMPONENT laser0.rtc",
                "2:15 COMPONENT lazer0",
                "3:13 PORT odometry0.rtc:odo",
                "3:44 COMPONENT odo_localise0.rtc",
                "3:70 PORT odo_localise0.rtc:odo",
                "4:5 MANAGER manager.mgr",
                "4:22 CREATED_TYPE odo_localise",
            ),
            read(text),
        )
    }

    @Test
    fun `comments are skipped, and names built at run time are said to be unknown`() {
        val text =
            """
            // component("commented.rtc")
            /* port("also:commented") */
            val name = args.first()
            on(component(name)).state(ERROR) { component("${'$'}name.rtc").port("scan") }
            val created = "x"
            log("component(\"inside.rtc\") in a string")
            """
                .trimIndent()
        assertEquals(
            listOf("4:14 COMPONENT (name)", "4:46 COMPONENT (\"${'$'}name.rtc\")", "4:64 PORT (\"scan\")"),
            read(text),
        )
    }

    @Test
    fun `network words and named arguments`() {
        val text =
            """
            modes("m") {
                mode("a") { network { active("a.rtc", "b.rtc"); connected(from = "a.rtc:out", to = "b.rtc:in"); inactive("c.rtc") } }
            }
            """
                .trimIndent()
        assertEquals(
            listOf("2:34 COMPONENT a.rtc", "2:43 COMPONENT b.rtc", "2:70 PORT a.rtc:out", "2:88 PORT b.rtc:in"),
            read(text),
        )
    }

    @Test
    fun `a component type is no name, and a glob with a type names the glob`() {
        assertEquals(
            listOf("2:11 COMPONENT laser*"),
            read("on(component(type = \"laser\")).state(ERROR) { }\ncomponent(\"laser*\", type = \"laser\")"),
        )
    }
}
