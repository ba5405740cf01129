package javax.safetycritical.annotate;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** The application phases in which a method or constructor may be called. */
@SCJAllowed
@Retention(RetentionPolicy.CLASS)
@Target({ElementType.TYPE, ElementType.METHOD, ElementType.CONSTRUCTOR})
public @interface SCJPhase {
    /** The permitted phases. */
    Phase[] value() default {Phase.STARTUP, Phase.INITIALIZATION, Phase.RUN, Phase.CLEANUP};
}
