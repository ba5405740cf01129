package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.MissionConfiguration;

/**
 * The mission's configuration with the P3 check around its localizer, through the seam the
 * mission offers ({@link MissionConfiguration#newLocalizer}). Seeded bugs subclass it and
 * replace {@link #localizer} (test sources only).
 */
public class CheckedConfiguration extends MissionConfiguration {

    public CheckedConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    public final Localizer newLocalizer(Playground playground, double startX, double startY, double startTheta) {
        return new CheckedLocalizer(localizer(playground, startX, startY, startTheta));
    }

    /** The localizer under check: the mission's own. */
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return super.newLocalizer(playground, startX, startY, startTheta);
    }
}
