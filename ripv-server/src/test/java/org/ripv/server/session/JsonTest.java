package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.LinkedHashMap;
import java.util.Map;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import org.ripv.json.Json;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;

class JsonTest {
    @Property(tries = 300)
    void anyTextSurvivesARoundTrip(@ForAll String text, @ForAll long n) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("text", text);
        m.put("n", n);
        m.put("none", null);
        m.put("yes", true);
        String line = Json.write(m);
        assertThat(line).doesNotContain("\n").doesNotContain("\r");
        assertThat(Json.parse(line)).isEqualTo(m);
    }

    @Property(tries = 300)
    void garbageIsRefusedNeverCrashes(@ForAll String junk) {
        try {
            Json.parse(junk);
        } catch (IllegalArgumentException expected) {
            // fine
        }
    }

    @Test
    void entriesRoundTripWithTheFieldsThatApply() {
        ConsoleEntry e = new ConsoleEntry(1_795_000_000_123L, "<S>::<h>ru29", ConsoleEntry.Kind.EVENT, "", "GPS", VehicleEvent.SURFACED,
                41.63323, -70.53647);
        String json = Entries.toJson(e);
        assertThat(json).isEqualTo("{\"time\":\"2026-11-18T11:06:40.123Z\",\"mailbox\":\"<S>::<h>ru29\",\"kind\":\"event\","
                + "\"text\":\"GPS\",\"event\":\"SURFACED\",\"lat\":41.63323,\"lon\":-70.53647}");
        assertThat(Entries.fromJson(json)).isEqualTo(e);
        ConsoleEntry c = new ConsoleEntry(5, "<S>::<h>ru29", ConsoleEntry.Kind.COMMAND, "alice", "dir", null, null, null);
        assertThat(Entries.fromJson(Entries.toJson(c))).isEqualTo(c);
    }

    @Test
    void overlongTextIsCutAndSaysSo() {
        ConsoleEntry e = ConsoleEntry.line("<S>::<h>ru29", "y".repeat(Entries.MAX_TEXT + 10));
        assertThat(Entries.fromJson(Entries.toJson(e)).text()).endsWith("[cut: 10 more characters]");
    }

    @Test
    void malformedTranscriptLinesAreRefused() {
        assertThatThrownBy(() -> Entries.fromJson("{\"time\":\"yesterday\",\"mailbox\":\"m\",\"kind\":\"line\"}"))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Entries.fromJson("{\"time\":\"2026-11-18T08:26:40Z\",\"mailbox\":\"m\",\"kind\":\"poem\"}"))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Json.parse("{\"a\":1} trailing")).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Json.parse("{\"a\":\"\\u12\"}")).isInstanceOf(IllegalArgumentException.class);
    }
}
