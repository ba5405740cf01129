package org.jmclbench.rtsjcompat;

import javax.realtime.MemoryArea;

/**
 * The bookkeeping of one memory area used as a budget (an SCJ area, or an RTSJ scoped memory,
 * whose parent is immortal memory): its stable name, its kind and nesting depth (the lifetime
 * order: immortal 0 &lt; mission 1 &lt; private 2 &lt; nested private 3, 4, ...), its size, and
 * the bytes charged to it.
 *
 * <p>An area is charged by the threads for which it is the current allocation context
 * ({@link ScjThread}); {@link #used} is what it holds since it was last emptied, {@link #peak}
 * the most it ever held (for a private area: the peak of one release), {@link #total} all
 * bytes ever charged and {@link #cycles} how often it was emptied (releases, for a private
 * area). Updates are synchronized on the area (mission memory can be charged by several
 * handlers at once) and allocate nothing.
 *
 * <p>For a verification listener: an object allocated while {@code a} is current lives in
 * {@code a}; a field of an object in area {@code x} may refer to an object in area
 * {@code y} only if {@link #mayHoldReferenceTo(Area) x.mayHoldReferenceTo(y)}.
 */
public final class Area {
    /** Immortal memory: lives for the whole application. */
    public static final int IMMORTAL = 0;
    /** Mission memory: lives for one mission. */
    public static final int MISSION = 1;
    /** A handler's private memory: lives for one release. */
    public static final int PRIVATE = 2;
    /** A private memory entered with {@code enterPrivateMemory}: lives while its logic runs. */
    public static final int NESTED = 3;
    /** An RTSJ scoped memory ({@code LTMemory}): lives while some thread is in it. */
    public static final int SCOPED = 4;

    /**
     * The names of the fields a verification listener reads from outside the program (Java
     * PathFinder's heap has no accessors to call): keep them in step with the fields below.
     */
    public static final String NAME_FIELD = "name";
    public static final String KIND_FIELD = "kind";
    public static final String DEPTH_FIELD = "depth";
    public static final String PARENT_FIELD = "parent";

    private final String name;
    private final int kind;
    private final int depth;
    private final Area parent;
    private final boolean enforced;
    private MemoryArea memoryArea;
    private long size;
    private long used;
    private long peak;
    private long total;
    private long cycles;
    // cycles in which something was charged: tells a one-off (a JIT compile request, docs) from a release that always allocates
    private long allocatingCycles;

    /** A new area whose budget is enforced; {@code parent} is the next longer-lived area (null for immortal). */
    public Area(String name, int kind, long size, Area parent) {
        this(name, kind, size, parent, true);
    }

    /** A new area; when not {@code enforced}, overflows are measured but raise nothing (warm-up launches). */
    public Area(String name, int kind, long size, Area parent, boolean enforced) {
        if (name == null) {
            throw new IllegalArgumentException("name is null");
        }
        if (size < 0) {
            throw new IllegalArgumentException(name + ": size is negative: " + size);
        }
        this.name = name;
        this.kind = kind;
        this.parent = parent;
        this.depth = parent == null ? 0 : parent.depth + 1;
        this.size = size;
        this.enforced = enforced;
    }

    /** Whether exceeding the size raises {@link AreaOverflowError}. */
    public boolean enforced() {
        return enforced;
    }

    /** The stable name, as reported in summary.json. */
    public String name() {
        return name;
    }

    /** {@link #IMMORTAL}, {@link #MISSION}, {@link #PRIVATE}, {@link #NESTED} or {@link #SCOPED}. */
    public int kind() {
        return kind;
    }

    /** The kind as a word: immortal, mission, private, nested, scoped. */
    public String kindName() {
        return kindName(kind);
    }

    /** A kind ({@link #IMMORTAL} ...) as a word: immortal, mission, private, scoped, or nested (any other). */
    public static String kindName(int kind) {
        switch (kind) {
            case IMMORTAL:
                return "immortal";
            case MISSION:
                return "mission";
            case PRIVATE:
                return "private";
            case SCOPED:
                return "scoped";
            default:
                return "nested";
        }
    }

    /** The nesting depth: 0 for immortal, one more per level inward (a shorter lifetime). */
    public int depth() {
        return depth;
    }

    /** The enclosing, longer-lived area (null for immortal). */
    public Area parent() {
        return parent;
    }

    /**
     * Whether an object in this area may refer to one in {@code other}: {@code other} must
     * live at least as long, that is be this area or one of its ancestors.
     */
    public boolean mayHoldReferenceTo(Area other) {
        for (Area a = this; a != null; a = a.parent) {
            if (a == other) {
                return true;
            }
        }
        return false;
    }

    /** The API object of this area (set once by its constructor). */
    public MemoryArea memoryArea() {
        return memoryArea;
    }

    /** Binds the API object; called by the {@code MemoryArea} constructor. */
    public void bind(MemoryArea area) {
        if (this.memoryArea != null) {
            throw new IllegalStateException(name + " is already bound");
        }
        this.memoryArea = area;
    }

    /** The size in bytes. */
    public synchronized long size() {
        return size;
    }

    /** Changes the size (mission memory, for each mission; a nested area at each entry). */
    public synchronized void resize(long newSize) {
        if (newSize < 0) {
            throw new IllegalArgumentException(name + ": size is negative: " + newSize);
        }
        this.size = newSize;
    }

    /** Bytes held since the area was last emptied. */
    public synchronized long used() {
        return used;
    }

    /** The most the area held at any time. */
    public synchronized long peak() {
        return peak;
    }

    /** All bytes ever charged. */
    public synchronized long total() {
        return total;
    }

    /** How many times the area was emptied. */
    public synchronized long cycles() {
        return cycles;
    }

    /** How many times the area was emptied holding something (a private area: releases that allocated). */
    public synchronized long allocatingCycles() {
        return allocatingCycles;
    }

    /** Adds {@code bytes}; returns the bytes held now (more than the size means overflow). */
    synchronized long charge(long bytes) {
        used += bytes;
        total += bytes;
        if (used > peak) {
            peak = used;
        }
        return used;
    }

    /** Frees everything the area holds (end of a release, of a mission). */
    public synchronized void empty() {
        if (used > 0) {
            allocatingCycles++;
        }
        used = 0;
        cycles++;
    }

    /** The error an SCJ VM raises when this area cannot hold {@code needed} bytes. */
    AreaOverflowError overflow(long needed) {
        return new AreaOverflowError(name, size(), needed);
    }

    @Override
    public String toString() {
        return name;
    }
}
