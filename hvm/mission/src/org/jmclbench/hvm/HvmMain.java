package org.jmclbench.hvm;

import javax.safetycritical.LaunchLevel1;
import javax.scj.util.Const;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.MclSafelet;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionSizes;

import vm.VMTest;

/**
 * The HVM executable's entry point: reads the run file (written by the tooling, which has
 * already validated the dataset and options), sets icecap's memory constants from the mission's
 * sizes, launches the MCL Safelet at Level 1 and writes the job records. Exit status 0 only when
 * the mission ended and its records were written.
 */
public final class HvmMain {
    static final long MAGIC = 0x314956484C434D4AL; // "JMCLHVI1", little-endian
    static final long VERSION = 1;
    /** Words before the area sizes: magic, version, 9 filter and policy fields, time scale. */
    static final int HEADER = 12;
    /**
     * What icecap's own Level 1 infrastructure places in immortal memory besides the mission's
     * data (its scheduler's queues, the processes and their stacks), in bytes.
     */
    static final int IMMORTAL_INFRASTRUCTURE = 1024 * 1024;
    /** The stacks of the mission's three handlers (int[STACK_WORDS] each), in bytes. */
    static final long HANDLER_STACKS = 3 * (4 * MissionSizes.STACK_WORDS + 64);
    /** Room for the bookkeeping of nested backing stores, in bytes. */
    static final int NESTING_SLACK = 256 * 1024;

    private HvmMain() {
    }

    public static void main(String[] args) {
        VMTest.markResult(true);
        if (HvmData.open() < HEADER || HvmData.word(0) != MAGIC || HvmData.word(1) != VERSION) {
            HvmData.fail(1);
            return;
        }
        MclConfig.Builder b = MclConfig.builder()
                .particles((int) HvmData.word(2))
                .estimate(MclConfig.Estimate.values()[(int) HvmData.word(3)])
                .resample(MclConfig.Resample.values()[(int) HvmData.word(4)])
                .init(MclConfig.Init.values()[(int) HvmData.word(5)])
                .memory(MclConfig.Memory.values()[(int) HvmData.word(6)])
                .seed(HvmData.word(7))
                .covariance(HvmData.word(8) != 0)
                .pollInterval((int) HvmData.word(9));
        OverrunPolicy policy = OverrunPolicy.ofCode(HvmData.word(10));
        MissionConfiguration config = new MissionConfiguration(b.build(), policy, HvmData.real(11));
        for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
            long size = HvmData.word(HEADER + a);
            if (size > 0) {
                config.areaSize(a, size);
            }
        }
        HvmInput input = new HvmInput(HEADER + MissionSizes.AREA_COUNT);
        if (config.areaSize(MissionSizes.MISSION) == 0) {
            // icecap allocates each handler's stack (ConfigurationParameters) in mission memory
            long computed = new MissionSizes(config, input.odometryCount(), input.laserCount())
                    .size(MissionSizes.MISSION);
            config.areaSize(MissionSizes.MISSION, computed + HANDLER_STACKS);
        }
        HvmOutput output = new HvmOutput();
        MclSafelet safelet = new MclSafelet(config, input, output);

        // icecap sizes its backing store and immortal memory from these constants, not from
        // the Safelet; the handlers' private memories are their ScopeParameters' sizes.
        MissionSizes sizes = safelet.sizes();
        Const.IMMORTAL_MEM = (int) (sizes.size(MissionSizes.IMMORTAL) + IMMORTAL_INFRASTRUCTURE);
        // icecap nests the areas: the mission memory inside the sequencer's private memory
        // (each of the mission's size), the handlers' private memories and their backing
        // stores inside the mission memory's reservation. The backing store is generous so
        // that the nesting fits; each area is still limited to its own size.
        Const.OVERALL_BACKING_STORE = (int) (Const.IMMORTAL_MEM + 2 * (sizes.size(MissionSizes.MISSION)
                + sizes.backingStore()) + NESTING_SLACK + Const.IDLE_BACKING_STORE);
        Const.OUTERMOST_SEQ_BACKING_STORE = Const.OVERALL_BACKING_STORE - Const.IMMORTAL_MEM
                - Const.IDLE_BACKING_STORE;
        Const.MISSION_MEM = (int) sizes.size(MissionSizes.MISSION);

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
