package org.jmclbench.tooling.generator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A scenario: where the robot starts, the route it follows, the default duration, and an
 * optional kidnapping (the robot is carried to another pose at a given time, with no
 * odometry for the jump). Routes are fixed; the seed changes only the sensor noise, the
 * missed detections and the turret's starting angle.
 */
public record Scenario(String name, String description, double defaultDuration, Pose start, List<Leg> route,
        boolean loop, Kidnap kidnap) {

    /** The robot is carried to {@code pose} right after the odometry reading at {@code time}. */
    public record Kidnap(double time, Pose pose) {
    }

    /** Eurobot-like match route: goal points all over the field, turns and short stops, looping. */
    private static List<Leg> matchRoute() {
        return List.of(
                new Leg.DriveTo(1.2, 0.5), new Leg.Wait(1.0),
                new Leg.DriveTo(2.2, 1.4), new Leg.TurnTo(Math.PI / 2), new Leg.Wait(1.5),
                new Leg.DriveTo(2.5, 0.5), new Leg.Wait(0.8),
                new Leg.DriveTo(1.5, 1.0), new Leg.TurnTo(Math.PI), new Leg.Wait(2.0),
                new Leg.DriveTo(0.6, 1.5), new Leg.Wait(1.0),
                new Leg.DriveTo(0.9, 0.6), new Leg.TurnTo(0.0), new Leg.Wait(1.0),
                new Leg.DriveTo(0.4, 0.4), new Leg.TurnTo(0.0), new Leg.Wait(1.0));
    }

    /** Gerono's lemniscate centred on the field: x = 1.5 + 1.1 sin s, y = 1 + 0.5 sin 2s. */
    private static Leg figureEight() {
        int n = 720;
        double[] xs = new double[n];
        double[] ys = new double[n];
        for (int i = 0; i < n; i++) {
            double s = 2 * Math.PI * i / n;
            xs[i] = 1.5 + 1.1 * StrictMath.sin(s);
            ys[i] = 1.0 + 0.5 * StrictMath.sin(2 * s);
        }
        return new Leg.FollowPath(xs, ys, 0.35);
    }

    private static final Pose MATCH_START = new Pose(0.4, 0.4, 0.0);

    private static final Map<String, Scenario> ALL;

    static {
        Map<String, Scenario> m = new LinkedHashMap<>();
        add(m, new Scenario("match", "a 90 s Eurobot-like match: drive between goal points, turn, stop briefly",
                90.0, MATCH_START, matchRoute(), true, null));
        add(m, new Scenario("match-short", "the first 20 s of the match route (the default dataset for quick runs)",
                20.0, MATCH_START, matchRoute(), true, null));
        add(m, new Scenario("stay", "standing still in the middle of the field (the thesis's stay case)",
                30.0, new Pose(1.5, 1.0, 0.0), List.of(new Leg.Wait(Double.POSITIVE_INFINITY)), false, null));
        add(m, new Scenario("figure8", "a figure-eight around the middle of the field at 0.35 m/s",
                60.0, new Pose(1.5, 1.0, StrictMath.atan2(1.0, 1.1)), List.of(figureEight()), false, null));
        add(m, new Scenario("kidnap", "the match route; at 30 s the robot is carried across the field with no odometry",
                60.0, MATCH_START, matchRoute(), true, new Kidnap(30.0, new Pose(2.3, 1.5, Math.PI))));
        ALL = Collections.unmodifiableMap(m);
    }

    private static void add(Map<String, Scenario> m, Scenario s) {
        m.put(s.name(), s);
    }

    /** The scenario of that name, or null. */
    public static Scenario byName(String name) {
        return ALL.get(name);
    }

    /** The names of all scenarios, in a fixed order. */
    public static List<String> names() {
        return new ArrayList<>(ALL.keySet());
    }

    /** All scenarios, in a fixed order. */
    public static List<Scenario> all() {
        return new ArrayList<>(ALL.values());
    }

    /** The same route from another start pose, for tests and experiments. */
    public Scenario withStart(Pose pose) {
        return new Scenario(name, description, defaultDuration, pose, route, loop, kidnap);
    }
}
