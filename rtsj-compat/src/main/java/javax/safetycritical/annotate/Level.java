package javax.safetycritical.annotate;

/** The SCJ compliance levels, plus SUPPORT for methods the infrastructure calls. */
@SCJAllowed
public enum Level {
    LEVEL_0, LEVEL_1, LEVEL_2, SUPPORT
}
