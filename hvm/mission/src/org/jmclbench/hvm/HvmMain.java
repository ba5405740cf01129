package org.jmclbench.hvm;

import javax.safetycritical.LaunchLevel1;
import javax.scj.util.Const;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.MclSafelet;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;

import vm.VMTest;

/**
 * The HVM executable's entry point: reads the run file (written by the tooling, which has
 * already validated the dataset and options), sets icecap's memory constants from the mission's
 * sizes, launches the MCL Safelet at Level 1 and writes the job records. Exit status 0 only when
 * the mission ended and its records were written.
 */
public final class HvmMain {
    private HvmMain() {
    }

    public static void main(String[] args) {
        VMTest.markResult(true);
        if (HvmData.open() < MissionRunFile.DATA || HvmData.word(MissionRunFile.MAGIC_WORD) != MissionRunFile.INPUT_MAGIC
                || HvmData.word(MissionRunFile.VERSION_WORD) != MissionRunFile.VERSION) {
            HvmData.fail(1);
            return;
        }
        MclConfig.Builder b = MclConfig.builder()
                .particles((int) HvmData.word(MissionRunFile.PARTICLES))
                .estimate(MissionRunFile.estimate(HvmData.word(MissionRunFile.ESTIMATE)))
                .resample(MissionRunFile.resample(HvmData.word(MissionRunFile.RESAMPLE)))
                .init(MissionRunFile.init(HvmData.word(MissionRunFile.INIT)))
                .memory(MissionRunFile.memory(HvmData.word(MissionRunFile.MEMORY)))
                .seed(HvmData.word(MissionRunFile.SEED))
                .covariance(HvmData.word(MissionRunFile.COVARIANCE) != 0)
                .pollInterval((int) HvmData.word(MissionRunFile.POLL_INTERVAL));
        OverrunPolicy policy = OverrunPolicy.ofCode(HvmData.word(MissionRunFile.POLICY));
        MissionConfiguration config = new MissionConfiguration(b.build(), policy, HvmData.real(MissionRunFile.TIME_SCALE));
        for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
            long size = HvmData.word(MissionRunFile.AREA_SIZES + a);
            if (size > 0) {
                config.areaSize(a, size);
            }
        }
        HvmInput input = new HvmInput(MissionRunFile.DATA);
        // icecap's own objects (its scheduler in immortal memory, each handler's stack in mission
        // memory) are added to computed sizes only, as the launcher reports them
        long[] icecap = MissionRunFile.icecapSizes(config,
                new MissionSizes(config, input.odometryCount(), input.laserCount()));
        config.areaSize(MissionSizes.MISSION, icecap[MissionSizes.MISSION]);
        HvmOutput output = new HvmOutput();
        MclSafelet safelet = new MclSafelet(config, input, output);

        // icecap sizes its backing store and immortal memory from these constants, not from
        // the Safelet; the handlers' private memories are their ScopeParameters' sizes. The
        // launcher refused sizes whose backing store the heap cannot hold (HvmLimits), so each
        // fits an int.
        Const.IMMORTAL_MEM = (int) icecap[MissionSizes.IMMORTAL];
        Const.IDLE_BACKING_STORE = (int) MissionRunFile.IDLE_BACKING_STORE;
        Const.OVERALL_BACKING_STORE = (int) MissionRunFile.overallBackingStore(icecap);
        Const.OUTERMOST_SEQ_BACKING_STORE = Const.OVERALL_BACKING_STORE - Const.IMMORTAL_MEM
                - Const.IDLE_BACKING_STORE;
        Const.MISSION_MEM = (int) icecap[MissionSizes.MISSION];

        new LaunchLevel1(safelet);

        if (!output.written()) {
            HvmData.fail(2);
            return;
        }
        if (HvmData.finish() != 0) {
            HvmData.fail(3);
            return;
        }
        VMTest.markResult(false);
    }
}
