package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** What jvms and doctor say of the HVM, from build-hvm.sh --check. */
class HvmRuntimeTest {

    @Test
    void withoutHvmSrcOnlyAToolChainNotCachedYetIsCloned() {
        // doctor warned "the source will be cloned from GitHub" beside a tool chain already cached
        HvmRuntime.Availability cached = HvmRuntime.availability(true, 0,
                "build-hvm: can be built (cached: /c/hvm/toolchain-ab)\n", false);
        assertEquals("can be built (cached: /c/hvm/toolchain-ab)", cached.detail());
        HvmRuntime.Availability fresh = HvmRuntime.availability(true, 0,
                "build-hvm: can be built (not cached yet: /c/hvm/toolchain-ab)\n", false);
        assertTrue(fresh.detail().endsWith("HVM_SRC is not set: the source will be cloned from GitHub (needs network)"),
                fresh.detail());
        assertFalse(HvmRuntime.availability(true, 0, "build-hvm: can be built (not cached yet: /x)", true).detail()
                .contains("cloned"), "HVM_SRC given: nothing is cloned");
        assertEquals("exit status 1", HvmRuntime.availability(false, 1, "", false).detail());
    }
}
