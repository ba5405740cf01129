package org.jmclbench.workload.output;

/**
 * A tiny dependency-free JSON writer (the workload may not depend on a library): objects,
 * arrays, strings with full escaping, numbers (NaN and infinities become null), two-space
 * indentation. Misuse (a value where a name is due) is the caller's bug, not checked.
 */
public final class Json {
    private final StringBuilder out = new StringBuilder();
    /** Per open container: whether it has no element yet. */
    private boolean[] empty = new boolean[16];
    private int depth;
    private boolean afterName;

    /** Opens an object (as a value). */
    public Json beginObject() {
        return open('{');
    }

    public Json endObject() {
        return close('}');
    }

    /** Opens an array (as a value). */
    public Json beginArray() {
        return open('[');
    }

    public Json endArray() {
        return close(']');
    }

    /** The name of the next member of the current object. */
    public Json name(String name) {
        separator();
        quote(name);
        out.append(": ");
        afterName = true;
        return this;
    }

    public Json value(String s) {
        beforeValue();
        if (s == null) {
            out.append("null");
        } else {
            quote(s);
        }
        return this;
    }

    public Json value(long v) {
        return literal(Long.toString(v));
    }

    /** A finite number as Java prints it; NaN and the infinities, which JSON lacks, as null. */
    public Json value(double v) {
        return literal(Double.isNaN(v) || Double.isInfinite(v) ? "null" : Double.toString(v));
    }

    public Json value(boolean v) {
        return literal(Boolean.toString(v));
    }

    /**
     * Any of null, String, Boolean, Number (integers as integers), a Map with String keys
     * (insertion order kept by the map) or an Iterable of those; anything else as its toString().
     */
    public Json any(Object v) {
        if (v == null) {
            return nullValue();
        }
        if (v instanceof Boolean) {
            return value(((Boolean) v).booleanValue());
        }
        if (v instanceof Long || v instanceof Integer || v instanceof Short || v instanceof Byte) {
            return value(((Number) v).longValue());
        }
        if (v instanceof Number) {
            return value(((Number) v).doubleValue());
        }
        if (v instanceof java.util.Map) {
            beginObject();
            for (java.util.Map.Entry<?, ?> e : ((java.util.Map<?, ?>) v).entrySet()) {
                name(String.valueOf(e.getKey()));
                any(e.getValue());
            }
            return endObject();
        }
        if (v instanceof Iterable) {
            beginArray();
            for (Object o : (Iterable<?>) v) {
                any(o);
            }
            return endArray();
        }
        return value(v.toString());
    }

    /** A null value. */
    public Json nullValue() {
        return literal("null");
    }

    /** A value written as {@code text}: a number, true, false or null. */
    private Json literal(String text) {
        beforeValue();
        out.append(text);
        return this;
    }

    /** The text written so far, with a final newline once the top level is closed. */
    @Override
    public String toString() {
        return depth == 0 ? out.toString() + "\n" : out.toString();
    }

    private void beforeValue() {
        if (afterName) {
            afterName = false;
            return;
        }
        separator();
    }

    private void separator() {
        if (depth == 0) {
            return;
        }
        if (!empty[depth - 1]) {
            out.append(',');
        }
        empty[depth - 1] = false;
        newline();
    }

    /** Opens a container, as a value, with {@code bracket}. */
    private Json open(char bracket) {
        beforeValue();
        out.append(bracket);
        if (depth == empty.length) {
            empty = java.util.Arrays.copyOf(empty, depth * 2);
        }
        empty[depth++] = true;
        return this;
    }

    /** Closes the innermost container with {@code bracket}, on a line of its own unless it is empty. */
    private Json close(char bracket) {
        boolean wasEmpty = empty[--depth];
        if (!wasEmpty) {
            newline();
        }
        out.append(bracket);
        return this;
    }

    private void newline() {
        out.append('\n');
        for (int i = 0; i < depth; i++) {
            out.append("  ");
        }
    }

    /** RFC 8259's two-character escapes: {@code ESCAPED.charAt(i)} is written as a backslash and {@code ESCAPE_LETTER.charAt(i)}. */
    private static final String ESCAPED = "\"\\\n\r\t\b\f";
    private static final String ESCAPE_LETTER = "\"\\nrtbf";

    private void quote(String s) {
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            int e = ESCAPED.indexOf(c);
            if (e >= 0) {
                out.append('\\').append(ESCAPE_LETTER.charAt(e));
            } else if (c < 0x20 || c == '\u2028' || c == '\u2029') {
                // Control characters, and U+2028/2029 which break JavaScript embedding.
                out.append(String.format("\\u%04x", (int) c));
            } else {
                out.append(c);
            }
        }
        out.append('"');
    }
}
