package org.rtcoord.sim.test

import java.nio.file.Path

/**
 * A test file and its [name]: its path relative to the directory it was found in (its file name when given by itself),
 * without `.test.kts`: `a/transient` for `tests/a/transient.test.kts` found in `tests/`. Names are unique within a run
 * (files of one name are named by the last parts of their paths that tell them apart), so that two reports never
 * collide.
 */
public class TestFile
internal constructor(
    /** The file, as given or found. */
    public val path: Path,
    /** Its name in reports, unique within a run. */
    public val name: String,
) {
    override fun toString(): String = path.toString()
}
