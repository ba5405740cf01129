package org.jmclbench.workload.output;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The JSON writer's structure and string escaping. */
class JsonTest {
    @Test
    void writesNestedStructures() {
        Json j = new Json();
        j.beginObject().name("a").value(1).name("b").beginArray().value("x").value(2.5).nullValue().endArray()
                .name("c").beginObject().endObject().name("d").value(Double.NaN).name("e").value(true).endObject();
        assertEquals("{\n  \"a\": 1,\n  \"b\": [\n    \"x\",\n    2.5,\n    null\n  ],\n  \"c\": {},\n"
                + "  \"d\": null,\n  \"e\": true\n}\n", j.toString());
    }

    @Test
    void writesMapsListsAndBoxedValues() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("i", 3);
        m.put("d", 0.5);
        m.put("b", false);
        m.put("n", null);
        m.put("l", java.util.Arrays.asList("a\"", 7L));
        assertEquals("{\n  \"i\": 3,\n  \"d\": 0.5,\n  \"b\": false,\n  \"n\": null,\n  \"l\": [\n    \"a\\\"\",\n"
                + "    7\n  ]\n}\n", new Json().any(m).toString());
    }

    @Test
    void escapesStrings() {
        Json j = new Json();
        j.beginArray().value("q\"b\\s/\n\r\t\b\f\u0001\u001f\u2028é</script>").value((String) null).endArray();
        assertEquals("[\n  \"q\\\"b\\\\s/\\n\\r\\t\\b\\f\\u0001\\u001f\\u2028é</script>\",\n  null\n]\n",
                j.toString());
    }
}
