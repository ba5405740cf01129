package javax.safetycritical.annotate;

/** Where a method may allocate, relative to its caller's allocation context. */
@SCJAllowed
public enum AllocationContext {
    CURRENT, OUTER, INNER, THIS
}
