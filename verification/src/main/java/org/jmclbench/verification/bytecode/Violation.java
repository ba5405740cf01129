package org.jmclbench.verification.bytecode;

/**
 * One finding of a static check, located as {@code class:method:line}.
 *
 * @param className the class, with dots
 * @param method    the method's name
 * @param line      the source line (0 when the class has no line numbers)
 * @param what      what is wrong there, and why it was looked at
 */
public record Violation(String className, String method, int line, String what) {

    /** {@code class:method:line}, the form every report uses. */
    public String location() {
        return className + ":" + method + ":" + line;
    }

    @Override
    public String toString() {
        return location() + " " + what;
    }
}
