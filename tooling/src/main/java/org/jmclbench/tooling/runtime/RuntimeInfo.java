package org.jmclbench.tooling.runtime;

import java.nio.file.Path;

/**
 * One runtime under test: a JVM (its {@code java} executable) or the native C baseline.
 *
 * @param name     short name used in results and run paths, e.g. {@code temurin-25}, {@code native}
 * @param kind     JVM, native or the icecap HVM (driven by the workload on the tool's JVM; docs/HVM.md)
 * @param vendor   {@code java.vendor}, or "native"
 * @param version  {@code java.runtime.version} (else {@code java.version}), or the native build's version
 * @param major    Java feature release (17, 25, ...); 0 for native
 * @param path     the executable as found (may be a symlink)
 * @param realPath the executable after resolving links: two paths with one real path are one runtime
 */
public record RuntimeInfo(String name, RuntimeKind kind, String vendor, String version, int major, Path path, Path realPath) {

    public boolean isJvm() {
        return kind == RuntimeKind.JVM;
    }

    /** A copy under another name (to tell two JVMs with the same vendor and major apart). */
    public RuntimeInfo withName(String newName) {
        return new RuntimeInfo(newName, kind, vendor, version, major, path, realPath);
    }
}
