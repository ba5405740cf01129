package javax.safetycritical.annotate;

/** The phases of an SCJ application in which a method may be called. */
@SCJAllowed
public enum Phase {
    CLEANUP, INITIALIZATION, RUN, STARTUP
}
