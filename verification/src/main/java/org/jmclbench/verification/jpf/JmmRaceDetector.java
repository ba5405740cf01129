package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.listener.PreciseRaceDetector;
import gov.nasa.jpf.vm.Instruction;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.bytecode.FieldInstruction;
import org.jmclbench.verification.Property;

import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;

/**
 * JPF's PreciseRaceDetector with the Java memory model's definition of a data race: two
 * conflicting accesses to a volatile field are synchronisation actions, not a race
 * (JLS 17.4.5), so a thread about to access a volatile field is left out of the candidates.
 * PreciseRaceDetector reports them, which would make the mission's volatile abort request a
 * false race. The race's two accesses are its locations.
 */
public final class JmmRaceDetector extends PreciseRaceDetector implements LocatedProperty {

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

    @Override
    public Property property() {
        return Property.P2;
    }

    /** The methods of the race's two accesses (PreciseRaceDetector keeps them in package-private fields). */
    @Override
    public List<String> locations() {
        Object r = race;
        List<String> at = new ArrayList<>();
        if (r == null) {
            return at;
        }
        for (String access : List.of("insn1", "insn2")) {
            try {
                Field f = field(r.getClass(), access);
                f.setAccessible(true);
                Instruction insn = (Instruction) f.get(r);
                if (insn != null) {
                    at.add(LocatedProperty.of(insn.getMethodInfo()));
                }
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException("PreciseRaceDetector's race has no field " + access, e);
            }
        }
        return at;
    }

    private static Field field(Class<?> c, String name) throws NoSuchFieldException {
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            for (Field f : k.getDeclaredFields()) {
                if (f.getName().equals(name)) {
                    return f;
                }
            }
        }
        throw new NoSuchFieldException(name);
    }
}
