package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.ListenerAdapter;
import gov.nasa.jpf.vm.FieldInfo;
import gov.nasa.jpf.vm.Instruction;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import gov.nasa.jpf.vm.bytecode.FieldInstruction;
import gov.nasa.jpf.vm.choice.ThreadChoiceFromSet;

/**
 * Makes every volatile field access of the mission's code a scheduling point. A volatile access
 * is a synchronisation action, like taking a monitor: in a program without data races, the
 * order of its synchronisation actions decides what it does. The mission checks break at
 * monitors (JPF does) and, with this listener, at volatiles, and not at plain field accesses;
 * P2 (no data race) is the check that makes that reduction sound.
 *
 * <p>The mission's volatiles are the policy rule's state ({@code OverrunPolicy.State}, which the
 * gate keeps): the latest admitted event, what a job's abort poll reads (without this point, a
 * release never falls between a job's start and its poll), and skip's reservation.
 *
 * <p>Configuration: {@code jmclbench.volatile.classes}, class-name prefixes of the code whose
 * volatile accesses break (default: the mission and the localizer, not the SCJ layer).
 */
public final class VolatileAccessScheduler extends ListenerAdapter {
    private final String[] classes;
    private final boolean timeoutLast;

    public VolatileAccessScheduler(Config config, JPF jpf) {
        this.timeoutLast = config.getBoolean("jmclbench.timeout.last", false);
        this.classes = config.getStringArray("jmclbench.volatile.classes", new String[] {"org.jmclbench.scj.", "org.jmclbench.core."});
    }

    @Override
    public void executeInstruction(VM vm, ThreadInfo ti, Instruction insn) {
        if (!(insn instanceof FieldInstruction) || ti.isFirstStepInsn()) {
            return; // a re-executed access (the choice was made) runs on
        }
        FieldInfo fi = ((FieldInstruction) insn).getFieldInfo();
        if (fi == null || !fi.isVolatile() || !inScope(insn.getMethodInfo().getClassName())) {
            return;
        }
        if (vm.getSystemState().isAtomic()) {
            return;
        }
        ThreadInfo[] runnable = vm.getThreadList().getProcessTimeoutRunnables(ti.getApplicationContext());
        if (timeoutLast) {
            runnable = AtomicRuntimeSyncPolicy.timeoutLast(runnable); // as the scheduling policy does
        }
        if (runnable.length < 2) {
            return;
        }
        if (vm.setNextChoiceGenerator(new ThreadChoiceFromSet("VOLATILE", runnable, true))) {
            ti.skipInstruction(insn); // executed again as the first step of the chosen thread's turn
        }
    }

    private boolean inScope(String cls) {
        for (String p : classes) {
            if (cls.startsWith(p)) {
                return true;
            }
        }
        return false;
    }
}
