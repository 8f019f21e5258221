package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;
import org.ripv.service.ReplySink;

/**
 * Issue 38: a query's rows leave the DatabaseServer in pages, the next only once the reader took
 * the one before (here a sink that paces pages as the server does, told by the test), so the
 * service never holds the result; the pages joined are every row in order; a cancel while the
 * query waits for its reader stops it, and the MailBox serves the next command at once.
 */
class QueryPagesTest {
    static final int ROWS = 20_000;
    static final String URL = "jdbc:derby:memory:queryPages";
    static final String CLIENT = "123456";
    static DatabaseServer service;
    static final BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    static String mailbox;
    static long ids;

    @BeforeAll
    static void start() throws Exception {
        try (Connection c = DriverManager.getConnection(URL + ";create=true"); Statement st = c.createStatement()) {
            st.execute("CREATE TABLE r (n INT PRIMARY KEY, label VARCHAR(40))");
            st.execute("INSERT INTO r VALUES (1, 'row 1')");
            // doubling 1 → 2 → 4 ... then cut at ROWS: a few statements, not ROWS of them
            for (int have = 1; have < ROWS; have *= 2) {
                st.execute("INSERT INTO r SELECT n + " + have + ", 'row ' || TRIM(CHAR(n + " + have + ")) FROM r WHERE n + "
                        + have + " <= " + ROWS);
            }
        }
        service = new DatabaseServer("testhost", List.of(DatabaseTarget.of("TTY1", URL, null, null)),
                new QueryLimits(1_000_000, 30, 1L << 30));
        service.start();
        service.replyTo(new ReplySink() {
            @Override
            public void reply(OutgoingServiceMessage r) {
                replies.add(r);
            }

            @Override
            public boolean pacesPages() {
                return true; // as the server: the test says when a page was taken
            }
        });
        mailbox = service.name().mailbox("TTY1").toString();
    }

    @AfterAll
    static void stop() {
        if (service != null) {
            service.stop();
        }
    }

    static long send(String sql) {
        long id = ++ids;
        service.accept(new IncomingServiceMessage(new Header(id, new IdBadge(CLIENT, "alice"), List.of("operators"),
                service.name().toString(), mailbox, sql, Priority.NORMAL, null)));
        return id;
    }

    static OutgoingServiceMessage next() throws InterruptedException {
        OutgoingServiceMessage r = replies.poll(60, TimeUnit.SECONDS);
        assertThat(r).as("a reply within 60 s").isNotNull();
        return r;
    }

    @Test
    void rowsComeInPagesOnlyAsTheReaderTakesThemAndJoinInOrder() throws Exception {
        long id = send("SELECT n, label FROM r ORDER BY n");
        TablePages pages = new TablePages();
        List<Integer> pageSizes = new ArrayList<>();
        int untaken = 0;
        OutgoingServiceMessage r = next();
        while (TablePages.isPage(r.footer())) {
            TableResult page = (TableResult) r.footer().result();
            pageSizes.add(page.rows().size());
            pages.add(page);
            untaken++;
            OutgoingServiceMessage more = null;
            if (untaken == 2) {
                // Two pages on their way and none taken: the next page waits (the final reply need not).
                more = replies.poll(300, TimeUnit.MILLISECONDS);
                assertThat(more == null || !TablePages.isPage(more.footer())).as("a third page before the reader took one").isTrue();
                assertThat(service.pageTaken(mailbox, CLIENT, id) || more != null).isTrue();
                untaken--;
            }
            r = more != null ? more : next();
        }
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        TableResult all = pages.join((TableResult) r.footer().result());
        assertThat(all.rows()).hasSize(ROWS);
        for (int i = 0; i < ROWS; i++) {
            assertThat(all.rows().get(i)[0]).isEqualTo(Integer.toString(i + 1));
            assertThat(all.rows().get(i)[1]).isEqualTo("row " + (i + 1));
        }
        assertThat(r.footer().replyText()).startsWith(ROWS + " rows in ");
        assertThat(pageSizes.get(0)).as("the first page is small, so the first rows come at once").isEqualTo(ResultPages.FIRST_PAGE_ROWS);
        assertThat(pageSizes.size()).as("pages " + pageSizes).isGreaterThan(3);
    }

    @Test
    void aCancelWhileTheQueryWaitsForItsReaderStopsItAndTheMailBoxServesOn() throws Exception {
        long id = send("SELECT a.n, b.label FROM r a, r b");
        assertThat(TablePages.isPage(next().footer())).isTrue();
        assertThat(TablePages.isPage(next().footer())).isTrue();
        // nobody takes a page: the query waits, holding no more rows
        assertThat(replies.poll(500, TimeUnit.MILLISECONDS)).isNull();
        assertThat(service.cancel(mailbox, CLIENT, id)).isTrue();
        OutgoingServiceMessage end = next();
        assertThat(end.status()).isEqualTo(Status.ERROR);
        assertThat(end.footer().errorCode()).as(end.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        long t0 = System.nanoTime();
        long id2 = send("SELECT COUNT(*) FROM r");
        OutgoingServiceMessage count = next();
        assertThat(count.header().messageId()).isEqualTo(id2);
        assertThat(((TableResult) count.footer().result()).rows().get(0)[0]).isEqualTo(Integer.toString(ROWS));
        assertThat((System.nanoTime() - t0) / 1_000_000).as("ms until the next command ran").isLessThan(10_000);
        assertThat(service.pageTaken(mailbox, CLIENT, id)).as("the cancelled query is no longer running").isFalse();
    }
}
