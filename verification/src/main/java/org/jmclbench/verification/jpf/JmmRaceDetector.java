package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.listener.PreciseRaceDetector;
import gov.nasa.jpf.vm.Instruction;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.bytecode.FieldInstruction;

/**
 * JPF's PreciseRaceDetector with the Java memory model's definition of a data race: two
 * conflicting accesses to a volatile field are synchronisation actions, not a race
 * (JLS 17.4.5), so a thread about to access a volatile field is left out of the candidates.
 * PreciseRaceDetector reports them, which would make the mission's volatile abort request a
 * false race.
 */
public final class JmmRaceDetector extends PreciseRaceDetector {

    public JmmRaceDetector(Config config) {
        super(config);
    }

    @Override
    protected boolean checkRace(ThreadInfo[] threads) {
        ThreadInfo[] plain = new ThreadInfo[threads.length];
        int n = 0;
        for (ThreadInfo ti : threads) {
            Instruction pc = ti.getPC();
            if (pc instanceof FieldInstruction fi && fi.getFieldInfo() != null && fi.getFieldInfo().isVolatile()) {
                continue;
            }
            plain[n++] = ti;
        }
        if (n == threads.length) {
            return super.checkRace(threads);
        }
        ThreadInfo[] kept = new ThreadInfo[n];
        System.arraycopy(plain, 0, kept, 0, n);
        return super.checkRace(kept);
    }
}
