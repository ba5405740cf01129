package org.jmclbench.rtsj.weaver;

/** A method the weaver cannot rewrite safely; the message names the class and method. */
public final class WeaveException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    WeaveException(String message) {
        super(message);
    }
}
