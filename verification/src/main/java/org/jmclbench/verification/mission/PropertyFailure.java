package org.jmclbench.verification.mission;

import org.jmclbench.verification.Property;

/**
 * A property the program under check found violated (P3, P4, P5), with where: the object whose
 * method broke it ({@code culprit}, its class) and that method. Verify matches a seeded bug's
 * expectation by the property and this location, read from Java PathFinder's heap, not by the
 * message. A check inside a release arms a failure made beforehand ({@link #at}), so that
 * reporting a violation allocates nothing (else the release-allocation rule would report it
 * first, as an allocation).
 */
public final class PropertyFailure extends AssertionError {
    private static final long serialVersionUID = 1L;
    /** The names of the fields a listener reads from Java PathFinder's heap. */
    public static final String PROPERTY_FIELD = "property";
    public static final String CULPRIT_FIELD = "culprit";
    public static final String METHOD_FIELD = "method";

    /** The violated property. */
    public final Property property;
    private Object culprit;
    private String method;

    /** A failure of {@code property}, to be located by {@link #at} before it is thrown. */
    public PropertyFailure(Property property, String what) {
        super(property.name() + " " + what);
        this.property = property;
    }

    /** Locates the violation at {@code culprit}'s {@code method}; returns this, to be thrown. */
    public PropertyFailure at(Object culprit, String method) {
        this.culprit = culprit;
        this.method = method;
        return this;
    }

    /** Where: "Class.method". */
    public String location() {
        return (culprit == null ? "?" : culprit.getClass().getName()) + "." + method;
    }

    /** Throws this failure, located at {@code culprit.method}, unless {@code ok}. */
    public void unless(boolean ok, Object culprit, String method) {
        if (!ok) {
            throw at(culprit, method);
        }
    }
}
