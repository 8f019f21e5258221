package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.InvalidObjectException;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Rows packed as a service reads them (PackedRows): they cross object streams as the same bytes,
 * are text only where they are read, and a hostile length is refused before anything is built.
 */
class PackedRowsTest {
    /** One value of every kind the DatabaseServer renders as text (DatabaseHandler.cell), with NULL. */
    private static final List<String> TYPES = List.of("INTEGER", "BIGINT", "SMALLINT", "DOUBLE", "REAL", "DECIMAL",
            "TIMESTAMP", "DATE", "TIME", "VARCHAR", "CHAR", "BOOLEAN", "CLOB", "BLOB");
    private static final String[] VALUES = {"-2147483648", "9223372036854775807", "7", "-1.5E-300", "3.4028235E38",
            "12345.6789", "2002-04-02 13:00:00.123456789", "2002-04-02", "13:00:00", "St. David's, Grüße 海 \uD83D\uDE80",
            "x   ", "true", "c".repeat(10_000) + "... (12000 characters)", "<EmbedBlob>"};

    private static PackedRows pack(List<String[]> rows, int width) {
        PackedRows.Builder b = PackedRows.builder(width);
        for (String[] row : rows) {
            for (String v : row) {
                b.cell(v);
            }
            b.endRow();
        }
        return b.build();
    }

    private static List<String[]> everyType() {
        List<String[]> rows = new ArrayList<>();
        rows.add(VALUES.clone());
        String[] nulls = new String[VALUES.length];
        rows.add(nulls);
        String[] empty = new String[VALUES.length];
        java.util.Arrays.fill(empty, "");
        rows.add(empty);
        return rows;
    }

    @Test
    void everyTypeAndNullComesBackAsTextAfterTheTrip() throws Exception {
        List<String[]> rows = everyType();
        TableResult t = new TableResult("SELECT *", TYPES, TYPES, pack(rows, TYPES.size()), false);
        assertThat(t.rows()).isInstanceOf(PackedRows.class).hasSize(3);
        TableResult back = (TableResult) PackedTableTest.roundTrip(t);
        assertThat(back.rows()).isInstanceOf(PackedRows.class).hasSize(3);
        for (int i = 0; i < rows.size(); i++) {
            assertThat(back.rows().get(i)).containsExactly(rows.get(i));
            assertThat(t.rows().get(i)).containsExactly(rows.get(i));
        }
        assertThat(back.types()).isEqualTo(TYPES);
    }

    @Test
    void aTableSentOnWritesTheBytesItCameAsAndIsNeverDecodedOnTheWay() throws Exception {
        List<String[]> rows = everyType();
        TableResult t = new TableResult("q", TYPES, TYPES, rows, true); // String rows, packed on writing
        TableResult relayed = (TableResult) PackedTableTest.roundTrip(t);
        TableResult again = (TableResult) PackedTableTest.roundTrip(relayed); // as the server relays a page
        assertThat(decoded(relayed)).as("the relay built no text").isNull();
        assertThat(((PackedRows) again.rows()).bytes()).isEqualTo(((PackedRows) relayed.rows()).bytes());
        assertThat(again.truncated()).isTrue();
        assertThat(again.rows().get(0)).containsExactly(VALUES);
        assertThat(again.rows().get(1)).containsOnlyNulls();

        // the server sends on the very array the page came in; a table with other columns or query gets its own
        Field data = PackedTable.class.getDeclaredField("data");
        data.setAccessible(true);
        assertThat(data.get(new PackedTable(relayed))).isSameAs(data.get(new PackedTable(relayed)));
        TableResult renamed = new TableResult("other query", relayed.columns(), relayed.types(), relayed.rows(), false);
        assertThat(data.get(new PackedTable(renamed))).isNotSameAs(data.get(new PackedTable(relayed)));
        TableResult back = (TableResult) PackedTableTest.roundTrip(renamed);
        assertThat(back.query()).isEqualTo("other query");
        assertThat(back.truncated()).isFalse();
        assertThat(back.rows().get(0)).containsExactly(VALUES);
    }

    @Test
    void aBuilderStartsAfreshAfterEachPageAndKeepsRowsWhole() {
        PackedRows.Builder b = PackedRows.builder(2);
        b.cell("1");
        assertThatThrownBy(b::endRow).isInstanceOf(IllegalStateException.class).hasMessageContaining("needs 2 values");
        assertThatThrownBy(b::build).isInstanceOf(IllegalStateException.class).hasMessageContaining("under way");
        b.cell(null);
        assertThatThrownBy(() -> b.cell("3")).isInstanceOf(IllegalStateException.class);
        b.endRow();
        PackedRows first = b.build();
        b.cell("a");
        b.cell("b");
        b.endRow();
        PackedRows second = b.build();
        assertThat(first).hasSize(1);
        assertThat(first.get(0)).containsExactly("1", null);
        assertThat(second.get(0)).containsExactly("a", "b");
        assertThat(b.build()).isEmpty();
        assertThatThrownBy(() -> second.get(1)).isInstanceOf(IndexOutOfBoundsException.class);
        assertThatThrownBy(() -> new TableResult("q", List.of("A"), List.of("INTEGER"), second, false))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("packed rows have 2");
    }

    @Test
    void hostileLengthsAreRefusedWithAClearErrorBeforeAnythingIsBuilt() throws Exception {
        TableResult t = new TableResult("q", List.of("A", "B"), List.of("VARCHAR", "VARCHAR"),
                List.<String[]>of(new String[] {"abc", "de"}), false);
        PackedTable p = new PackedTable(t);
        Field data = PackedTable.class.getDeclaredField("data");
        data.setAccessible(true);
        byte[] good = (byte[]) data.get(p);
        int lastLengthAt = good.length - 2 - 4; // ... len("abc"), "abc", len("de"), "de"

        byte[] tooLong = good.clone();
        putInt(tooLong, lastLengthAt, 1 << 30); // a cell claiming a gigabyte
        data.set(p, tooLong);
        assertThatThrownBy(() -> PackedTableTest.roundTrip(p)).isInstanceOf(InvalidObjectException.class)
                .hasMessageContaining("string length 1073741824 does not fit its data");

        byte[] negative = good.clone();
        putInt(negative, lastLengthAt, -7);
        data.set(p, negative);
        assertThatThrownBy(() -> PackedTableTest.roundTrip(p)).isInstanceOf(InvalidObjectException.class)
                .hasMessageContaining("string length -7");

        byte[] shorter = good.clone();
        putInt(shorter, lastLengthAt, 1); // one byte of "de": a byte left after the last row
        data.set(p, shorter);
        assertThatThrownBy(() -> PackedTableTest.roundTrip(p)).isInstanceOf(InvalidObjectException.class)
                .hasMessageContaining("1 bytes after its last row");

        data.set(p, java.util.Arrays.copyOf(good, good.length - 3)); // cut inside the last length
        assertThatThrownBy(() -> PackedTableTest.roundTrip(p)).isInstanceOf(InvalidObjectException.class)
                .hasMessageContaining("cut short");
    }

    @Test
    void joinedPagesAreOneTableWithoutASecondCopy() {
        TablePages pages = new TablePages();
        List<String[]> a = List.<String[]>of(new String[] {"1", "x"}, new String[] {"2", null});
        pages.add(new TableResult("q", List.of("N", "S"), List.of("INTEGER", "VARCHAR"), pack(a, 2), false));
        TableResult last = new TableResult("q", List.of("N", "S"), List.of("INTEGER", "VARCHAR"),
                pack(List.<String[]>of(new String[] {"3", "z"}), 2), true);
        TableResult all = pages.join(last);
        assertThat(all.rows()).hasSize(3);
        assertThat(all.rows().get(1)).containsExactly("2", null);
        assertThat(all.rows().get(2)).containsExactly("3", "z");
        assertThat(all.truncated()).isTrue();
        assertThatThrownBy(() -> all.rows().add(new String[2])).isInstanceOf(UnsupportedOperationException.class);

        // a page of another width is not trusted: the joined table is checked, and refused
        TablePages mixed = new TablePages();
        mixed.add(new TableResult("q", List.of("N"), List.of("INTEGER"), pack(List.<String[]>of(new String[] {"1"}), 1), false));
        assertThatThrownBy(() -> mixed.join(last)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("every row needs 2 values");
    }

    @Test
    void joinedPagesStayPackedUntilARowOfThemIsRead() throws Exception {
        TablePages pages = new TablePages();
        TableResult first = new TableResult("q", List.of("N"), List.of("INTEGER"),
                pack(List.<String[]>of(new String[] {"1"}, new String[] {"2"}), 1), false);
        pages.add(first);
        TableResult all = pages.join(new TableResult("q", List.of("N"), List.of("INTEGER"),
                pack(List.<String[]>of(new String[] {"3"}), 1), false));
        assertThat(decoded(first)).as("a reader holds a page's bytes, not its Strings, until it reads a row").isNull();
        assertThat(all.rows().get(2)).containsExactly("3");
        assertThat(decoded(first)).as("a row of another page leaves this one packed").isNull();
        assertThat(all.rows()).extracting(r -> r[0]).containsExactly("1", "2", "3");
        assertThat(decoded(first)).isNotNull();
    }

    private static Object decoded(TableResult t) throws Exception {
        Field f = PackedRows.class.getDeclaredField("decoded");
        f.setAccessible(true);
        return f.get(t.rows());
    }

    private static void putInt(byte[] b, int at, int v) {
        b[at] = (byte) (v >>> 24);
        b[at + 1] = (byte) (v >>> 16);
        b[at + 2] = (byte) (v >>> 8);
        b[at + 3] = (byte) v;
    }
}
