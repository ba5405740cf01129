package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * A runtime profile: components joined by {@code +} ({@code g1+fifo+pinned}); {@code default} is the
 * JVM as it comes (its default GC and JIT, no scheduling change).
 */
public record Profile(String name, List<ProfileComponent> components) {

    public static final String DEFAULT = "default";

    public static Profile defaultProfile() {
        return new Profile(DEFAULT, List.of());
    }

    /**
     * Parses {@code g1+fifo}; the canonical name keeps the order given.
     *
     * @throws BadUsageException naming {@code where} (an option or file:line) on an unknown or conflicting component
     */
    public static Profile parse(String text, String where) {
        String t = text.trim();
        if (t.isEmpty()) {
            throw new BadUsageException(where + ": empty profile name");
        }
        if (t.equals(DEFAULT)) {
            return defaultProfile();
        }
        List<ProfileComponent> comps = new ArrayList<>();
        Map<ProfileComponent.Category, ProfileComponent> seen = new EnumMap<>(ProfileComponent.Category.class);
        for (String part : t.split("\\+", -1)) {
            String id = part.trim();
            ProfileComponent c = ProfileComponent.byId(id).orElseThrow(() -> new BadUsageException(
                    where + ": unknown profile component '" + id + "' in '" + text + "' (known: " + known() + ")"));
            if (comps.contains(c)) {
                throw new BadUsageException(where + ": '" + id + "' twice in profile '" + text + "'");
            }
            ProfileComponent other = c.category() == ProfileComponent.Category.OS ? null : seen.put(c.category(), c);
            if (other != null) {
                throw new BadUsageException(where + ": profile '" + text + "' has two " + c.category().name().toLowerCase()
                        + " settings: " + other.id() + " and " + id);
            }
            comps.add(c);
        }
        return new Profile(comps.stream().map(ProfileComponent::id).collect(Collectors.joining("+")), List.copyOf(comps));
    }

    /**
     * What a run of that kind keeps of this profile ({@link ProfileComponent#appliesTo}): a native
     * run only the OS components, the HVM those, {@code int} and {@code hot}; {@code default} when none is left.
     */
    public Profile effectiveFor(RuntimeKind kind) {
        List<ProfileComponent> kept = components.stream().filter(c -> c.appliesTo(kind)).toList();
        if (kept.isEmpty()) {
            return defaultProfile();
        }
        return new Profile(kept.stream().map(ProfileComponent::id).collect(Collectors.joining("+")), kept);
    }

    /**
     * The icecap HVM's mode of this profile: {@code interpreted} with {@code int}, {@code hot} with
     * {@code hot}, else {@code compiled} (docs/HVM.md).
     */
    public String hvmMode() {
        return has(ProfileComponent.INT) ? "interpreted" : has(ProfileComponent.HOT) ? "hot" : "compiled";
    }

    public boolean has(ProfileComponent c) {
        return components.contains(c);
    }

    public static String known() {
        return DEFAULT + ", " + Arrays.stream(ProfileComponent.values()).map(ProfileComponent::id).collect(Collectors.joining(", "));
    }
}
