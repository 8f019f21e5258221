package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.LinkedHashMap;
import java.util.Map;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import org.ripv.json.JsonWriter;

/** The files Jackson writes now are the bytes RIPV's own writer wrote, so old and new lines read alike. */
class JsonBytesTest {
    @Property(tries = 500)
    void sameBytesAsTheOldWriter(@ForAll String text, @ForAll long n, @ForAll double d, @ForAll boolean b) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("text", text);
        m.put(text, n);
        m.put("d", d);
        m.put("b", b);
        m.put("none", null);
        assertThat(Json.write(m)).isEqualTo(JsonWriter.write(m));
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
    void onlyFlatObjectsAreRead() {
        assertThat(Json.parse(" {\"a\":1,\"b\":1.5,\"c\":123456789012345678901,\"d\":false} ")).containsEntry("a", 1L)
                .containsEntry("b", 1.5).containsEntry("c", 1.2345678901234568E20).containsEntry("d", false);
        for (String bad : new String[] {"", "5", "[1]", "{\"a\":[1]}", "{\"a\":{}}", "{\"a\":1}{", "{'a':1}"}) {
            assertThatThrownBy(() -> Json.parse(bad)).as(bad).isInstanceOf(IllegalArgumentException.class);
        }
    }
}
