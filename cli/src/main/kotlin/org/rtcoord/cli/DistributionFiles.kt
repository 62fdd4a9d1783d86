package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/**
 * Writes the files the distribution archive carries besides the jars (the man page and the shell completion scripts)
 * below the folder given as the only argument. Run by the build, before packaging.
 */
internal object DistributionFiles {
    @JvmStatic
    fun main(args: Array<String>) {
        val top = Paths.get(args.single())
        write(top.resolve("share/man/man1/rtcoord.1"), ManPage.render(Rtcoord.version()))
        write(top.resolve("share/bash-completion/completions/rtcoord"), CompletionCommand.completionScript("bash"))
        write(top.resolve("share/zsh/site-functions/_rtcoord"), CompletionCommand.completionScript("zsh"))
        write(top.resolve("share/fish/vendor_completions.d/rtcoord.fish"), CompletionCommand.completionScript("fish"))
    }

    private fun write(file: Path, text: String) {
        Files.createDirectories(file.parent)
        Files.writeString(file, text)
    }
}
