package org.rtcoord.cli.json

import kotlinx.serialization.KSerializer
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.PrimitiveSerialDescriptor
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.encoding.Decoder
import kotlinx.serialization.encoding.Encoder

/**
 * A double as a JSON number, or as the text `NaN`, `Infinity` or `-Infinity`, which JSON has no number for (a context's
 * rate before it is set, a rate measured over no time). Use it on every `Double`.
 */
internal object FiniteDouble : KSerializer<Double> {
    override val descriptor: SerialDescriptor =
        PrimitiveSerialDescriptor("org.rtcoord.cli.json.FiniteDouble", PrimitiveKind.DOUBLE)

    override fun serialize(encoder: Encoder, value: Double) {
        if (value.isFinite()) encoder.encodeDouble(value) else encoder.encodeString(value.toString())
    }

    override fun deserialize(decoder: Decoder): Double = decoder.decodeString().toDouble()
}
