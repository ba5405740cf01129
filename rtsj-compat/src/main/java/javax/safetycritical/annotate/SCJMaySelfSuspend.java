package javax.safetycritical.annotate;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** Whether a method may block its caller (sleep, wait for a lock held elsewhere, I/O). */
@SCJAllowed
@Retention(RetentionPolicy.CLASS)
@Target({ElementType.TYPE, ElementType.METHOD, ElementType.CONSTRUCTOR})
public @interface SCJMaySelfSuspend {
    /** True when the element may self-suspend. */
    boolean value() default false;
}
