package org.rtcoord.runtime

/** A loadable module, as a shared library is for OpenRTM: a file name and the component types it provides. */
public class RuntimeModule(public val fileName: String, public val types: List<ComponentType>)
