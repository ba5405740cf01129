package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.List;

/** The kernel's CPU list syntax ({@code 0-2,5}). */
public final class CpuList {
    private CpuList() {
    }

    /**
     * Parses {@code 0-2,5} into [0, 1, 2, 5]; an empty text is an empty list.
     *
     * @throws IllegalArgumentException for anything else ({@code -}, {@code 1-}, {@code 3-1}, {@code 1-2-3}, {@code x})
     */
    public static List<Integer> parse(String text) {
        List<Integer> out = new ArrayList<>();
        for (String part : text.trim().split(",")) {
            if (part.isBlank()) {
                continue;
            }
            // -1 keeps the empty ends, so that "-" and "1-" are bad ranges, not an index past the array
            String[] range = part.trim().split("-", -1);
            if (range.length > 2) {
                throw new IllegalArgumentException("bad CPU range " + part);
            }
            int from = Integer.parseInt(range[0].trim());
            int to = range.length > 1 ? Integer.parseInt(range[1].trim()) : from;
            if (to < from) {
                throw new IllegalArgumentException("bad CPU range " + part);
            }
            for (int i = from; i <= to; i++) {
                out.add(i);
            }
        }
        return out;
    }
}
