package org.jmclbench.verification.rtsj;

import org.jmclbench.verification.CheckCatalog;
import org.jmclbench.verification.StaticCheck;
import org.jmclbench.verification.jpf.JpfCheck;

import java.util.List;

/** The checks of the rtsj engine: its lock and ATC correctness under JPF ({@link RtsjChecks}). */
public final class RtsjCatalog implements CheckCatalog {
    @Override
    public String name() {
        return "rtsj";
    }

    @Override
    public List<JpfCheck> jpfChecks() {
        return RtsjChecks.all();
    }

    @Override
    public List<StaticCheck> staticChecks() {
        return List.of();
    }
}
