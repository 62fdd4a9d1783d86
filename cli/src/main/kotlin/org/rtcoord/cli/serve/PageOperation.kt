package org.rtcoord.cli.serve

import org.rtcoord.ComponentNode
import org.rtcoord.RtcTree

/**
 * What the page may do to a component when the server lets it operate, as rtshell's commands do: rtact, rtdeact,
 * rtreset, rtexit, rtcon and rtdis on a port, rtconf's set and act. [parameters] are the request's query parameters
 * each needs besides the component's path.
 */
internal enum class PageOperation(
    val word: String,
    val parameters: List<String>,
    val perform: suspend (tree: RtcTree, component: ComponentNode, given: Map<String, String>) -> Unit,
) {
    ACTIVATE("activate", emptyList(), { _, component, _ -> component.activate() }),
    DEACTIVATE("deactivate", emptyList(), { _, component, _ -> component.deactivate() }),
    RESET("reset", emptyList(), { _, component, _ -> component.reset() }),
    EXIT("exit", emptyList(), { _, component, _ -> component.exit() }),

    /** Connects the component's `port` to the port at path `to`. */
    CONNECT(
        "connect",
        listOf("port", "to"),
        { tree, component, given ->
            component.port(given.getValue("port")).connect(listOf(tree.port(given.getValue("to"))))
        },
    ),

    /** Removes connector `connector` of the component's `port`. */
    DISCONNECT(
        "disconnect",
        listOf("port", "connector"),
        { _, component, given ->
            component.port(given.getValue("port")).disconnect(given.getValue("connector"))
        },
    ),

    /** Writes `value` to parameter `name` of configuration set `set`. */
    SET(
        "set",
        listOf("set", "name", "value"),
        { _, component, given ->
            component.setParameter(given.getValue("name"), given.getValue("value"), given.getValue("set"))
        },
    ),

    /** Makes configuration set `set` the active one. */
    ACTIVATE_SET(
        "activate-set",
        listOf("set"),
        { _, component, given -> component.activateConfigurationSet(given.getValue("set")) },
    );

    companion object {
        /** The operation named [word], or null. */
        fun named(word: String?): PageOperation? = entries.firstOrNull { it.word == word }

        /** The words of every operation, for an error that lists them. */
        val words: String
            get() = entries.joinToString { it.word }
    }
}
