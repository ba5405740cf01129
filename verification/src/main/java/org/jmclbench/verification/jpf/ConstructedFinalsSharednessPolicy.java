package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.FieldInfo;
import gov.nasa.jpf.vm.Instruction;
import gov.nasa.jpf.vm.PathSharednessPolicy;
import gov.nasa.jpf.vm.ThreadInfo;

/**
 * JPF's sharedness policy, except that a final field of an object whose constructor has returned
 * is never a point to switch threads, even in a type the search always breaks on: JPF's own
 * {@code vm.shared.skip_constructed_finals} rule, applied before {@code vm.shared.always_break_types}
 * (JPF applies it after, so that an always-break type switches at every final field too). Such a
 * read cannot race: a final field is written only by the constructor, and the Java memory model
 * (JLS 17.5) has every thread that sees the object after that see the written value, so no
 * interleaving around the read changes what any thread does.
 *
 * <p>Why: the P2 searches break on every field access of the mission's types, and a handler's
 * release reads several final fields (its runner, the runner's output and area); each read was a
 * switch point that multiplied the states searched without adding a behaviour.
 */
public class ConstructedFinalsSharednessPolicy extends PathSharednessPolicy {

    public ConstructedFinalsSharednessPolicy(Config config) {
        super(config);
    }

    @Override
    public boolean canHaveSharedObjectCG(ThreadInfo ti, Instruction insn, ElementInfo owner, FieldInfo fi) {
        if (fi != null && fi.isFinal() && owner.isConstructed()) {
            return false;
        }
        return super.canHaveSharedObjectCG(ti, insn, owner, fi);
    }
}
