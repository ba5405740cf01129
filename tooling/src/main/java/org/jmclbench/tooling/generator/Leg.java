package org.jmclbench.tooling.generator;

/** One part of a scenario's route, what the route-following controller works on. */
public sealed interface Leg {

    /** Drive to a goal point (turning on the spot first when it lies far off the heading) and stop there. */
    record DriveTo(double x, double y) implements Leg {
    }

    /** Turn on the spot to a heading. */
    record TurnTo(double theta) implements Leg {
    }

    /** Stand still for a while. */
    record Wait(double seconds) implements Leg {
    }

    /**
     * Follow a closed path forever at a cruise speed (pure pursuit); the points are dense
     * enough that the straight pieces between them are short.
     */
    record FollowPath(double[] xs, double[] ys, double cruise) implements Leg {
    }
}
