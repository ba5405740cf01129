package org.jmclbench.verification.jpf;

import gov.nasa.jpf.vm.serialize.FieldAmmendmentByName;

/**
 * Leaves out of JPF's state matching the fields that hold a reading of the host's clock and
 * decide nothing: under JPF {@code System.nanoTime()} is the host's time, different on every
 * path, so two states that differ only there would never match and the search would explore
 * the same interleavings again (the atomic design's search grew from 1,502 to 7,027 states). No
 * property reads them: they become the recorded times of a job, not its outcome.
 */
public final class IgnoreClockReadings extends FieldAmmendmentByName {
    /** Fully qualified field names: when a delivery point of the atomic design threw the AIE. */
    static final String[] FIELDS = {"org.jmclbench.workload.rtsj.DeliveryPoints$WitnessedInterrupt.deliveredNanoTime"};

    public IgnoreClockReadings() {
        super(FIELDS, POLICY_IGNORE);
    }
}
