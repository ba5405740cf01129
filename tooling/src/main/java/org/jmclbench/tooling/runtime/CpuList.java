package org.jmclbench.tooling.runtime;

import java.util.ArrayList;
import java.util.List;

/** The kernel's CPU list syntax ({@code 0-2,5}). */
public final class CpuList {
    private CpuList() {
    }

    /** Parses {@code 0-2,5} into [0, 1, 2, 5]; an empty text is an empty list. */
    public static List<Integer> parse(String text) {
        List<Integer> out = new ArrayList<>();
        for (String part : text.trim().split(",")) {
            if (part.isBlank()) {
                continue;
            }
            String[] range = part.trim().split("-");
            int from = Integer.parseInt(range[0].trim());
            int to = range.length > 1 ? Integer.parseInt(range[1].trim()) : from;
            if (to < from || range.length > 2) {
                throw new IllegalArgumentException("bad CPU range " + part);
            }
            for (int i = from; i <= to; i++) {
                out.add(i);
            }
        }
        return out;
    }
}
