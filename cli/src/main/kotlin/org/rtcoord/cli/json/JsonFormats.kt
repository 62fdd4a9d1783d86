package org.rtcoord.cli.json

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.ClassDiscriminatorMode
import kotlinx.serialization.json.Json

/**
 * JSON as rtcoord writes it on one line: `watch --json` and `print --json` (one object a line), the live view's API and
 * recordings. No class discriminator is written: a type that varies names itself in a field of its own (an event's
 * `event`, a watch method's `method`). A property with a default value is left out while it holds it: that is how a
 * field that does not apply is absent rather than null.
 */
@OptIn(ExperimentalSerializationApi::class)
internal val OneLineJson: Json = Json {
    classDiscriminatorMode = ClassDiscriminatorMode.NONE
}

/** JSON as the `--json` reports print it: [OneLineJson] indented by two spaces. */
@OptIn(ExperimentalSerializationApi::class)
internal val PrettyJson: Json =
    Json(OneLineJson) {
        prettyPrint = true
        prettyPrintIndent = "  "
    }
