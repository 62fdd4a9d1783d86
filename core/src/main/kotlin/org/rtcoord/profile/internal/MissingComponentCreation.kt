package org.rtcoord.profile.internal

import org.rtcoord.DirectoryNode
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfileRefusedException

/**
 * Creates a profile's missing components through managers, as RTSystemEditor's "restore with creation" does: each
 * through the manager bound nearest its `pathUri` (its own naming context, then the contexts above it), a master before
 * a slave, by the type its component id names and its instance name.
 */
internal class MissingComponentCreation(private val tree: RtcTree) {
    /** A missing component and the manager that is to create it. */
    class Planned(val component: ProfileComponent, val path: String, val type: String, val manager: ManagerNode)

    /** A manager for each of [missing]; refused, before anything is created, when one has none or names no type. */
    suspend fun plan(missing: List<ProfileComponent>): List<Planned> = missing.map { c ->
        val path = "/" + c.pathUri.removePrefix("/")
        val type =
            c.id.split(':').getOrNull(3)?.takeIf { it.isNotBlank() }
                ?: throw ProfileRefusedException(
                    "$path: component id '${c.id}' names no type to create (RTC:vendor:category:type:version)"
                )
        Planned(
            c,
            path,
            type,
            managerFor(RtcPath(path))
                ?: throw ProfileRefusedException("$path: no manager in its naming context or above it to create it"),
        )
    }

    /** Creates [planned]'s component; returns what was done, one line. */
    suspend fun create(planned: Planned): String {
        val node =
            try {
                planned.manager.create(planned.type, planned.component.instanceName)
            } catch (e: RtcException) {
                throw ProfileRefusedException("cannot create ${planned.path}: ${e.message}")
            }
        return "created ${planned.path} (${planned.type}) through ${planned.manager.path}" +
            if (node.path.toString() == planned.path) "" else ", listed at ${node.path}"
    }

    /** Deletes what [create] made, as a refused restore leaves the system as it found it. */
    suspend fun delete(planned: Planned) {
        planned.manager.delete(planned.component.instanceName)
    }

    /** The manager bound in [path]'s naming context or the nearest one above it; a master first. */
    private suspend fun managerFor(path: RtcPath): ManagerNode? {
        var context = path.parent
        while (context != null && !context.isRoot) {
            val managers = listed(context).filterIsInstance<ManagerNode>()
            managers
                .firstOrNull { answering { it.isMaster() } == true }
                ?.let {
                    return it
                }
            managers.firstOrNull()?.let {
                return it
            }
            context = context.parent
        }
        return null
    }

    /** What the directory at [path] holds; nothing when it is not a directory or does not answer. */
    private suspend fun listed(path: RtcPath): List<Node> = answering {
        (tree.node(path) as? DirectoryNode)?.children()
    }
        .orEmpty()

    private suspend fun <T> answering(read: suspend () -> T): T? =
        try {
            read()
        } catch (e: RtcException) {
            null
        }
}
