package javax.safetycritical.annotate;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** The allocation contexts a method or constructor may allocate in; an empty list means it allocates nothing. */
@SCJAllowed
@Retention(RetentionPolicy.CLASS)
@Target({ElementType.TYPE, ElementType.METHOD, ElementType.CONSTRUCTOR})
public @interface SCJMayAllocate {
    /** The permitted contexts. */
    AllocationContext[] value() default {AllocationContext.CURRENT, AllocationContext.OUTER, AllocationContext.INNER};
}
