package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.wire.WireFilter;

/** A TableResult crosses object streams as one packed array and comes back equal; bad packed data is refused. */
class PackedTableTest {
    static Object roundTrip(Object o) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(b.toByteArray()))) {
            in.setObjectInputFilter(WireFilter.forFrames(16 << 20));
            return in.readObject();
        }
    }

    @Test
    void tablesSurviveTheTripWithNullsAndUnicode() throws Exception {
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"1", "St. David's", null});
        rows.add(new String[] {"2", "Grüße 海", ""});
        TableResult t = new TableResult("SELECT * FROM vehicle", List.of("ID", "NAME", "NOTE"),
                List.of("INTEGER", "VARCHAR", "VARCHAR"), rows, true);
        Footer f = Footer.ok(Ids.SID_DATABASE, "2 rows", t);
        TableResult back = (TableResult) ((Footer) roundTrip(f)).result();
        assertThat(back.query()).isEqualTo(t.query());
        assertThat(back.columns()).isEqualTo(t.columns());
        assertThat(back.types()).isEqualTo(t.types());
        assertThat(back.truncated()).isTrue();
        assertThat(back.rows()).hasSize(2);
        assertThat(back.rows().get(0)).containsExactly("1", "St. David's", null);
        assertThat(back.rows().get(1)).containsExactly("2", "Grüße 海", "");

        TableResult empty = new TableResult("", List.of(), List.of(), List.of(), false);
        TableResult e = (TableResult) roundTrip(empty);
        assertThat(e.columns()).isEmpty();
        assertThat(e.rows()).isEmpty();
    }

    @Test
    void aLargeTableIsOneArrayNotAnObjectPerCell() throws Exception {
        List<String[]> rows = new ArrayList<>();
        for (int i = 0; i < 100_000; i++) {
            rows.add(new String[] {Integer.toString(i), "2002-04-02 13:00:00.0", "20.5"});
        }
        TableResult t = new TableResult("q", List.of("A", "B", "C"), List.of("INTEGER", "TIMESTAMP", "DOUBLE"), rows, false);
        TableResult back = (TableResult) roundTrip(t);
        assertThat(back.rows()).hasSize(100_000);
        assertThat(back.rows().get(99_999)[0]).isEqualTo("99999");
    }

    @Test
    void corruptPackedDataIsRefused() throws Exception {
        PackedTable p = new PackedTable(new TableResult("q", List.of("A"), List.of("INTEGER"),
                List.<String[]>of(new String[] {"1"}), false));
        Field data = PackedTable.class.getDeclaredField("data");
        data.setAccessible(true);
        byte[] good = (byte[]) data.get(p);
        // a row count far beyond the bytes sent must not make the reader allocate for it
        byte[] huge = good.clone();
        int rowCountAt = good.length - 4 - 4 - 1; // ... rowCount, len("1"), '1'
        huge[rowCountAt] = 0x7f;
        data.set(p, huge);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("count");
        data.set(p, java.util.Arrays.copyOf(good, good.length - 1));
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class);
        data.set(p, new byte[] {0, 0, 0, 9});
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("version");
    }
}
