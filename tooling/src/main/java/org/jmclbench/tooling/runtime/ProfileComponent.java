package org.jmclbench.tooling.runtime;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * One named building block of a runtime profile: a GC, a JIT mode, heap pre-touch, OS scheduling and
 * power management, AOT.
 * {@link #appliesTo} says which runtime kinds take it: the others drop it from their profile. The
 * heap size, a number, is no constant here: {@link Profile#heapMb()}.
 */
public enum ProfileComponent {
    SERIAL(Category.GC, "Serial GC", "-XX:+UseSerialGC"),
    PARALLEL(Category.GC, "Parallel GC", "-XX:+UseParallelGC"),
    G1(Category.GC, "G1 GC", "-XX:+UseG1GC"),
    ZGC(Category.GC, "ZGC", "-XX:+UseZGC"),
    SHENANDOAH(Category.GC, "Shenandoah GC", "-XX:+UseShenandoahGC"),
    /** Allocates, never collects: needs a heap big enough for the whole run. */
    EPSILON(Category.GC, "Epsilon (no-op) GC, " + ProfileComponent.EPSILON_HEAP_MB + " MB heap",
            "-XX:+UnlockExperimentalVMOptions", "-XX:+UseEpsilonGC"),
    /** A JVM's -Xint; on the icecap HVM, its interpreter instead of the mission compiled to C. */
    INT(Category.JIT, "interpreter only", "-Xint"),
    C1(Category.JIT, "C1 only", "-XX:TieredStopAtLevel=1"),
    /** The icecap HVM only: the hot methods compiled to C (hvm/mission/hot-methods.txt), the rest interpreted. */
    HOT(Category.JIT, "hot methods compiled to C, the rest interpreted (icecap HVM only)"),
    /** Commits and touches the whole heap at start, so that no page fault happens while measuring. */
    PRETOUCH(Category.HEAP, "pre-touched fixed heap (-Xms=-Xmx)", "-XX:+AlwaysPreTouch"),
    FIFO(Category.OS, "SCHED_FIFO priority " + ProfileComponent.FIFO_PRIORITY + " via chrt"),
    PINNED(Category.OS, "pinned to one CPU via taskset"),
    /**
     * No deep CPU idle states while the run lasts: {@code /dev/cpu_dma_latency} held at 0, as
     * cyclictest does. A CPU that sleeps between jobs wakes late and, on a VM, may run the job slower.
     */
    NOIDLE(Category.OS, "CPUs kept out of deep idle states: " + IdleStateHold.DEVICE + " held at 0 (as cyclictest does)"),
    AOT(Category.AOT, "AOT cache (JDK 25+) or AppCDS archive (JDK 13+) trained on a short run");

    /** The heap of an Epsilon run: preallocated runs allocate little; allocating ones ~100 MB a minute. */
    public static final int EPSILON_HEAP_MB = 2048;
    /** The heap of a pre-touched run when nothing else (a heap size component, Epsilon) asks for a size. */
    public static final int PRETOUCH_HEAP_MB = 512;
    /** SCHED_FIFO priority of the runtime under test (cyclictest's usual 80, below the kernel's 99 threads). */
    public static final int FIFO_PRIORITY = 80;

    /** Components of one category exclude each other (two GCs, two JIT modes). */
    public enum Category { GC, JIT, HEAP, OS, AOT }

    private final Category category;
    private final String description;
    private final List<String> flags;

    ProfileComponent(Category category, String description, String... flags) {
        this.category = category;
        this.description = description;
        this.flags = List.of(flags);
    }

    public Category category() {
        return category;
    }

    public String description() {
        return description;
    }

    /** JVM flags of this component alone (heap sizes and prefixes are added by {@link LaunchPlan}). */
    public List<String> flags() {
        return flags;
    }

    /**
     * Whether a runtime of this kind takes the component: a JVM every one; a native program only
     * scheduling and pinning; the icecap HVM those, {@code int} (its interpreter) and {@code hot} (only
     * the hot methods compiled; compiled to C is its default, docs/HVM.md), which no JVM takes.
     */
    public boolean appliesTo(RuntimeKind kind) {
        return switch (kind) {
            case JVM -> this != HOT;
            case NATIVE -> category == Category.OS;
            case HVM -> category == Category.OS || this == INT || this == HOT;
        };
    }

    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static Optional<ProfileComponent> byId(String id) {
        return Arrays.stream(values()).filter(c -> c.id().equals(id)).findFirst();
    }
}
