package org.jmclbench.rtsjcompat;

/**
 * Loads and initialises this layer's own classes before a launch, on the caller's thread,
 * so that the bytes a JVM allocates to load them (class file buffers, mirrors) are not
 * charged to the application's memory areas. An SCJ VM has no class loading at run time;
 * an application's own classes should be loaded the same way before the launch (see the
 * README).
 */
final class Preload {
    static final String[] CLASSES = {
            "javax.realtime.AbsoluteTime",
            "javax.realtime.Affinity",
            "javax.realtime.AperiodicParameters",
            "javax.realtime.AsyncBaseEventHandler",
            "javax.realtime.AsyncEvent",
            "javax.realtime.AsyncEventHandler",
            "javax.realtime.AsynchronouslyInterruptedException",
            "javax.realtime.BoundAbstractAsyncEventHandler",
            "javax.realtime.BoundAsyncEventHandler",
            "javax.realtime.Chronograph",
            "javax.realtime.Clock",
            "javax.realtime.ConfigurationParameters",
            "javax.realtime.HighResolutionTime",
            "javax.realtime.ImmortalMemory",
            "javax.realtime.Interruptible",
            "javax.realtime.LTMemory",
            "javax.realtime.MemoryArea",
            "javax.realtime.MemoryParameters",
            "javax.realtime.PeriodicParameters",
            "javax.realtime.PriorityParameters",
            "javax.realtime.PriorityScheduler",
            "javax.realtime.ProcessingGroupParameters",
            "javax.realtime.RealtimeClock",
            "javax.realtime.RealtimeThread",
            "javax.realtime.RelativeTime",
            "javax.realtime.ReleaseParameters",
            "javax.realtime.Schedulable",
            "javax.realtime.Scheduler",
            "javax.realtime.SchedulingParameters",
            "javax.realtime.ScopedMemory",
            "javax.realtime.ShallowCloneable",
            "javax.realtime.memory.ScopeParameters",
            "javax.safetycritical.AperiodicEventHandler",
            "javax.safetycritical.CyclicExecutive",
            "javax.safetycritical.CyclicExecutor",
            "javax.safetycritical.CyclicSchedule",
            "javax.safetycritical.Frame",
            "javax.safetycritical.Launch",
            "javax.safetycritical.LaunchLevel0",
            "javax.safetycritical.LaunchLevel1",
            "javax.safetycritical.LinearMissionSequencer",
            "javax.safetycritical.ManagedEventHandler",
            "javax.safetycritical.ManagedMemory",
            "javax.safetycritical.ManagedSchedulable",
            "javax.safetycritical.Mission",
            "javax.safetycritical.MissionMemory",
            "javax.safetycritical.MissionSequencer",
            "javax.safetycritical.OneShotEventHandler",
            "javax.safetycritical.PeriodicEventHandler",
            "javax.safetycritical.PriorityScheduler",
            "javax.safetycritical.PrivateMemory",
            "javax.safetycritical.Safelet",
            "javax.safetycritical.Services",
            "org.jmclbench.rtsjcompat.AllocationMeter",
            "org.jmclbench.rtsjcompat.AperiodicRuntime",
            "org.jmclbench.rtsjcompat.Area",
            "org.jmclbench.rtsjcompat.AreaOverflowError",
            "org.jmclbench.rtsjcompat.AreaUsage",
            "org.jmclbench.rtsjcompat.Arguments",
            "org.jmclbench.rtsjcompat.Atc",
            "org.jmclbench.rtsjcompat.AtcState",
            "org.jmclbench.rtsjcompat.HandlerRuntime",
            "org.jmclbench.rtsjcompat.HandlerServer",
            "org.jmclbench.rtsjcompat.HandlerSetup",
            "org.jmclbench.rtsjcompat.HandlerStats",
            "org.jmclbench.rtsjcompat.IdleParticipant",
            "org.jmclbench.rtsjcompat.Installed",
            "org.jmclbench.rtsjcompat.MissionControl",
            "org.jmclbench.rtsjcompat.MissionFailure",
            "org.jmclbench.rtsjcompat.Named",
            "org.jmclbench.rtsjcompat.ObjectAreaResolver",
            "org.jmclbench.rtsjcompat.OneShotRuntime",
            "org.jmclbench.rtsjcompat.PeriodicRuntime",
            "org.jmclbench.rtsjcompat.Preload",
            "org.jmclbench.rtsjcompat.Priorities",
            "org.jmclbench.rtsjcompat.RtsjRuntime",
            "org.jmclbench.rtsjcompat.RunReport",
            "org.jmclbench.rtsjcompat.RunState",
            "org.jmclbench.rtsjcompat.ScjLauncher",
            "org.jmclbench.rtsjcompat.ScjRuntime",
            "org.jmclbench.rtsjcompat.ScjThread",
            "org.jmclbench.rtsjcompat.SystemTimeSource",
            "org.jmclbench.rtsjcompat.TimeSource",
            "org.jmclbench.rtsjcompat.VirtualTimeSource",
    };

    private Preload() {
    }

    static void run() {
        ClassLoader loader = Preload.class.getClassLoader();
        for (String name : CLASSES) {
            try {
                Class.forName(name, true, loader);
            } catch (ClassNotFoundException e) {
                throw new IllegalStateException("rtsj-compat is incomplete: " + name, e);
            }
        }
    }

    /** Loads {@code classes} (an application's) before the launch; see {@link ScjRuntime#preload(String...)}. */
    static void run(String... classes) {
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        for (String name : classes) {
            try {
                Class.forName(name, true, loader == null ? Preload.class.getClassLoader() : loader);
            } catch (ClassNotFoundException e) {
                throw new IllegalArgumentException("no such class to preload: " + name, e);
            }
        }
    }
}
