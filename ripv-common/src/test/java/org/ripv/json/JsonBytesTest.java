package org.ripv.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

/**
 * The lines Jackson writes are the bytes RIPV's own hand-written writer wrote before it (its
 * escaping rule is the oracle here), so transcripts and subscription files written by older
 * servers and newer ones read alike, and scripts reading {@code --json} see no change.
 */
class JsonBytesTest {
    @Property(tries = 500)
    void sameBytesAsTheOldWriter(@ForAll String text, @ForAll long n, @ForAll double d, @ForAll boolean b) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("text", text);
        m.put(text, n);
        m.put("d", d);
        m.put("b", b);
        m.put("none", null);
        m.put("list", Arrays.asList(text, n, null));
        String expected = "{" + quote("text") + ":" + quote(text) + "," + quote(text) + ":" + n + "," + quote("d") + ":"
                + (Double.isFinite(d) ? Double.toString(d) : "null") + "," + quote("b") + ":" + b + "," + quote("none")
                + ":null," + quote("list") + ":[" + quote(text) + "," + n + ",null]}";
        assertThat(Json.write(m)).isEqualTo(expected);
    }

    @Test
    void controlsAndLineSeparatorsAreEscapedInLowerCase() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("t", "a\b\f\u001b\u007f\u009b\u2028\u2029\u00e9\"\\/\n\r\t");
        m.put("nan", Double.NaN);
        assertThat(Json.write(m)).isEqualTo("{\"t\":\"a\\u0008\\u000c\\u001b\\u007f\\u009b\\u2028\\u2029\u00e9\\\"\\\\/\\n\\r\\t\","
                + "\"nan\":null}");
    }

    @Test
    void numbersKeepTheirDigitsAndOtherObjectsTheirText() {
        assertThat(Json.write(List.of(new BigInteger("123456789012345678901"), new BigDecimal("10.10"), 2.5f, Float.NaN,
                new Object[] {1, "x"}, Thread.State.NEW))).isEqualTo("[123456789012345678901,10.10,2.5,null,[1,\"x\"],\"NEW\"]");
    }

    @Test
    void onlyFlatObjectsAreRead() {
        assertThat(Json.parse(" {\"a\":1,\"b\":1.5,\"c\":123456789012345678901,\"d\":false} ")).containsEntry("a", 1L)
                .containsEntry("b", 1.5).containsEntry("c", 1.2345678901234568E20).containsEntry("d", false);
        for (String bad : new String[] {"", "5", "[1]", "{\"a\":[1]}", "{\"a\":{}}", "{\"a\":1}{", "{'a':1}"}) {
            assertThatThrownBy(() -> Json.parse(bad)).as(bad).isInstanceOf(IllegalArgumentException.class);
        }
    }

    /** The old writer's string rule: JSON's escapes, every other control, DEL, C1 and U+2028/2029 as lower-case hex. */
    private static String quote(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> b.append(c < 0x20 || c >= 0x7f && c <= 0x9f || c == 0x2028 || c == 0x2029
                        ? String.format("\\u%04x", (int) c) : String.valueOf(c));
            }
        }
        return b.append('"').toString();
    }
}
