package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Pages of a table join in order; a reader's bound cuts and marks the table; only PROGRESS with a table is a page. */
class TablePagesTest {
    private static TableResult rows(int from, int to, boolean truncated) {
        List<String[]> r = new ArrayList<>();
        for (int i = from; i < to; i++) {
            r.add(new String[] {Integer.toString(i)});
        }
        return new TableResult("SELECT n FROM t", List.of("N"), List.of("INTEGER"), r, truncated);
    }

    @Test
    void pagesJoinInOrderWithTheFinalRows() {
        TablePages p = new TablePages();
        p.add(rows(0, 100, false));
        p.add(rows(100, 300, false));
        TableResult all = p.join(rows(300, 350, true));
        assertThat(all.rows()).extracting(r -> r[0]).containsExactlyElementsOf(
                java.util.stream.IntStream.range(0, 350).mapToObj(Integer::toString).toList());
        assertThat(all.truncated()).as("the final reply says whether the whole was cut").isTrue();
        assertThat(all.columns()).containsExactly("N");
    }

    @Test
    void aTableInOneReplyIsUnchanged() {
        TableResult one = rows(0, 5, false);
        assertThat(new TablePages().join(one)).isSameAs(one);
    }

    @Test
    void theReadersBoundCutsAndMarksTheTable() {
        TablePages p = new TablePages(250);
        p.add(rows(0, 200, false));
        p.add(rows(200, 400, false));
        TableResult all = p.join(rows(400, 450, false));
        assertThat(all.rows()).hasSize(250);
        assertThat(all.rows().get(249)[0]).isEqualTo("249");
        assertThat(all.rows()).extracting(r -> r[0]).containsExactlyElementsOf(
                java.util.stream.IntStream.range(0, 250).mapToObj(Integer::toString).toList());
        assertThat(all.truncated()).isTrue();
    }

    @Test
    void onlyProgressWithATableIsAPage() {
        assertThat(TablePages.isPage(Footer.progress("666666", "rows 1-100", rows(0, 100, false)))).isTrue();
        assertThat(TablePages.isPage(Footer.progress("666666", "50 %", new Progress("x", 1, 2, 0)))).isFalse();
        assertThat(TablePages.isPage(Footer.ok("666666", "4 rows", rows(0, 4, false)))).isFalse();
    }
}
