package org.rtcoord.profile.internal

import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile

// Apart from RtsProfiles: a `when` over the enum compiles to a class of its own, which Java would see in the API
// package.

/** The profile in [text], written in [format]; [source] names it in errors. */
internal fun readProfile(text: String, format: ProfileFormat, source: String): RtsProfile =
    when (format) {
        ProfileFormat.XML -> XmlProfileReader(source).read(text)
        ProfileFormat.YAML -> YamlProfileReader(source).read(text)
    }

/** [profile] as text in [format]. */
internal fun writeProfile(profile: RtsProfile, format: ProfileFormat): String =
    when (format) {
        ProfileFormat.XML -> XmlProfileWriter().write(profile)
        ProfileFormat.YAML -> YamlProfileWriter().write(profile)
    }
