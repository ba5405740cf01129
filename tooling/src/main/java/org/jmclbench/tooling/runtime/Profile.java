package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * A runtime profile: components joined by {@code +} ({@code g1+fifo+pinned}); {@code default} is the
 * JVM as it comes (its default GC and JIT, no scheduling change).
 *
 * @param heapMb the JVM's maximum heap a {@code heap<N>m} or {@code heap<N>g} component sets, in
 *               MiB; 0 when the profile sets none
 */
public record Profile(String name, List<ProfileComponent> components, int heapMb) {

    public static final String DEFAULT = "default";

    /** The heap size component: {@code heap512m}, {@code heap4g} (the -Xmx of the JVM under test). */
    private static final Pattern HEAP = Pattern.compile("heap([0-9]{1,7})([mg])");
    /** The largest heap a profile may ask for, 1 TiB in MiB (a bigger one is a typo, not a setting). */
    public static final int MAX_HEAP_MB = 1 << 20;

    public static Profile defaultProfile() {
        return new Profile(DEFAULT, List.of(), 0);
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
        List<String> ids = new ArrayList<>();
        int heapMb = 0;
        Map<ProfileComponent.Category, ProfileComponent> seen = new EnumMap<>(ProfileComponent.Category.class);
        for (String part : t.split("\\+", -1)) {
            String id = part.trim();
            Matcher heap = HEAP.matcher(id);
            if (heap.matches()) {
                if (heapMb > 0) {
                    throw new BadUsageException(where + ": profile '" + text + "' has two heap sizes");
                }
                long mb = Long.parseLong(heap.group(1)) * (heap.group(2).equals("g") ? 1024 : 1);
                if (mb < 1 || mb > MAX_HEAP_MB) {
                    throw new BadUsageException(where + ": '" + id + "' in '" + text + "': a heap of 1m to "
                            + (MAX_HEAP_MB / 1024) + "g");
                }
                heapMb = (int) mb;
                ids.add(heapId(heapMb));
                continue;
            }
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
            ids.add(c.id());
        }
        return new Profile(String.join("+", ids), List.copyOf(comps), heapMb);
    }

    /** A heap size's canonical component, so that {@code heap1024m} and {@code heap1g} are one profile. */
    private static String heapId(int mb) {
        return mb % 1024 == 0 ? "heap" + mb / 1024 + "g" : "heap" + mb + "m";
    }

    /**
     * What a run of that kind keeps of this profile ({@link ProfileComponent#appliesTo}): a native
     * run only the OS components, the HVM those, {@code int} and {@code hot}, and only a JVM the heap
     * size; {@code default} when none is left.
     */
    public Profile effectiveFor(RuntimeKind kind) {
        if (components.isEmpty() && heapMb == 0) {
            return this;
        }
        List<String> kept = Arrays.stream(name.split("\\+"))
                .filter(id -> ProfileComponent.byId(id).map(c -> c.appliesTo(kind)).orElse(kind == RuntimeKind.JVM))
                .toList();
        return kept.isEmpty() ? defaultProfile() : parse(String.join("+", kept), name);
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
        return DEFAULT + ", " + Arrays.stream(ProfileComponent.values()).map(ProfileComponent::id).collect(Collectors.joining(", "))
                + ", heap<N>m, heap<N>g";
    }
}
