package org.rtcoord.profile

import java.nio.file.Files
import java.nio.file.Path
import org.rtcoord.profile.internal.readProfile
import org.rtcoord.profile.internal.writeProfile

/** The two forms of an RTSProfile file; [RtsProfiles.formatOf] tells a file's. */
public enum class ProfileFormat {
    XML,
    YAML,
}

/** A profile file that cannot be read: [message] names the file, the line and what is wrong. */
public class ProfileFormatException(
    /** The file (or `-` for standard input). */
    public val source: String,
    /** The line, from 1; 0 when unknown. */
    public val line: Int,
    /** What is wrong. */
    public val reason: String,
) : Exception(if (line > 0) "$source:$line: $reason" else "$source: $reason")

/** Reads and writes RTSProfile files, XML or YAML, as RTSystemEditor and rtshell (rtsprofile) do. */
public object RtsProfiles {
    /** Reads the profile in [file], in the form its name or content says. */
    @JvmStatic
    @Throws(ProfileFormatException::class)
    public fun read(file: Path): RtsProfile {
        val text =
            try {
                Files.readString(file)
            } catch (e: java.io.IOException) {
                throw ProfileFormatException(file.toString(), 0, "cannot read: ${e.message ?: e.javaClass.simpleName}")
            }
        return parse(text, formatOf(file.fileName.toString(), text), file.toString())
    }

    /** The form a file named [fileName] has by its extension (`.yaml`/`.yml`: YAML), else by its [text]. */
    @JvmStatic
    public fun formatOf(fileName: String, text: String): ProfileFormat =
        when {
            fileName.endsWith(".yaml", ignoreCase = true) || fileName.endsWith(".yml", ignoreCase = true) ->
                ProfileFormat.YAML
            fileName.endsWith(".xml", ignoreCase = true) -> ProfileFormat.XML
            text.trimStart().startsWith("<") -> ProfileFormat.XML
            else -> ProfileFormat.YAML
        }

    /** Reads a profile from [text] in [format]; [source] names it in errors. */
    @JvmStatic
    @JvmOverloads
    @Throws(ProfileFormatException::class)
    public fun parse(text: String, format: ProfileFormat, source: String = "-"): RtsProfile =
        readProfile(text, format, source)

    /** [profile] as text in [format]. */
    @JvmStatic public fun write(profile: RtsProfile, format: ProfileFormat): String = writeProfile(profile, format)
}
