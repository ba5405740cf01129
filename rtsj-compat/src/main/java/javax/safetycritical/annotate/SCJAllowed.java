package javax.safetycritical.annotate;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** Marks an API element as part of SCJ at the given compliance level (checked by tools, not at run time). */
@SCJAllowed
@Retention(RetentionPolicy.CLASS)
@Target({ElementType.TYPE, ElementType.FIELD, ElementType.METHOD, ElementType.CONSTRUCTOR})
public @interface SCJAllowed {
    /** Whether the members inherit the annotation. */
    boolean members() default false;

    /** The lowest compliance level at which the element may be used. */
    Level value() default Level.LEVEL_0;
}
