package org.jmclbench.rtsjcompat;

import java.util.ArrayList;
import java.util.List;

/**
 * The RTSJ side of this layer, outside any SCJ launch: the handler servers started so far, the
 * first failure of a handler, and the memory areas RTSJ code created (immortal memory and the
 * scoped memories), with their measured use. An engine resets it before a run, reads the areas
 * and the failure after it, and ends the handlers with {@link #stopHandlers(long)}.
 */
public final class RtsjRuntime {
    private static final List<HandlerServer> SERVERS = new ArrayList<HandlerServer>();
    private static final List<Area> AREAS = new ArrayList<Area>();
    private static Area immortal;
    private static MissionFailure failure;

    private RtsjRuntime() {
    }

    static synchronized void register(HandlerServer s) {
        SERVERS.add(s);
    }

    /** Records the first failure ({@code where}: the handler or thread it escaped from). */
    public static synchronized void fail(String where, Throwable cause) {
        if (failure == null) {
            failure = new MissionFailure(where, cause);
        }
    }

    /** The first failure since the last {@link #reset()}, or null. */
    public static synchronized MissionFailure failure() {
        return failure;
    }

    /**
     * Stops every handler server (each ends after the fires pending now), waits up to
     * {@code timeoutMs} in all for their threads, and returns the names of those still running
     * (a handler that never ends: the caller records it as the run's failure).
     */
    public static List<String> stopHandlers(long timeoutMs) {
        List<HandlerServer> all;
        synchronized (RtsjRuntime.class) {
            all = new ArrayList<HandlerServer>(SERVERS);
            SERVERS.clear();
        }
        for (HandlerServer s : all) {
            s.stop();
        }
        long end = System.nanoTime() + timeoutMs * 1000000L;
        List<String> alive = new ArrayList<String>();
        for (HandlerServer s : all) {
            long left = Math.max(1, (end - System.nanoTime()) / 1000000L);
            try {
                s.thread().join(left);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (s.thread().isAlive()) {
                alive.add(s.name());
            }
        }
        return alive;
    }

    /** RTSJ's immortal memory outside an SCJ launch: measured, never enforced (its size is the VM's). */
    public static synchronized Area immortal() {
        if (immortal == null) {
            immortal = new Area("ImmortalMemory", Area.IMMORTAL, Long.MAX_VALUE, null, false);
            AREAS.add(immortal);
        }
        return immortal;
    }

    /** A new scoped memory of {@code size} bytes (enforced), named after its class and creation order. */
    public static synchronized Area newScope(String kindName, long size) {
        Area a = new Area(kindName + "#" + (AREAS.size()), Area.SCOPED, size, immortal(), true);
        AREAS.add(a);
        return a;
    }

    /** What every RTSJ area received since the last {@link #reset()}. */
    public static synchronized List<AreaUsage> areas() {
        List<AreaUsage> u = new ArrayList<AreaUsage>();
        for (Area a : AREAS) {
            u.add(new AreaUsage(a));
        }
        return u;
    }

    /** Forgets the failure and the areas (before a run); the handlers must have been stopped. */
    public static synchronized void reset() {
        failure = null;
        AREAS.clear();
        immortal = null;
    }
}
