package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * How fast the GuiManager turns replies into model changes on the real Swing event queue (the
 * headless AWT event thread): text replies for the COM panel and 100-row tables for the DAB
 * panel. Run with {@code -Dripv.bench=true}; figures in docs/client.md.
 */
class DispatchBenchmarkTest {
    static final String SVC = "<DatabaseServer>::<h>";

    @Test
    void dispatchThroughput() throws Exception {
        assumeTrue(Boolean.getBoolean("ripv.bench"), "benchmark: run with -Dripv.bench=true");
        ClientModel model = new ClientModel();
        try (GuiManager m = new GuiManager(model, SwingUtilities::invokeLater, (h, p) -> {
            throw new IOException("offline");
        }, GuiManager.Timings.DEFAULT)) {
            m.dispatch(reply(0, Ids.FID_SERVICES, "", new ServiceList(List.of(
                    new ServiceDescriptor(SVC, Ids.SID_DATABASE, "", "DAB", List.of())))));
            List<String[]> rows = new ArrayList<>();
            for (int i = 0; i < 100; i++) {
                rows.add(new String[] {Integer.toString(i), "name " + i, "2001-06-0" + (i % 9 + 1)});
            }
            TableResult table = new TableResult("SELECT * FROM MISSION", List.of("ID", "NAME", "STARTT"),
                    List.of("INTEGER", "VARCHAR", "DATE"), rows, false);
            for (int round = 0; round < 3; round++) {
                int n = 100_000;
                long t0 = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    m.dispatch(reply(i, Ids.SID_DATABASE, "line " + i, null));
                }
                SwingUtilities.invokeAndWait(() -> { });
                double text = n / ((System.nanoTime() - t0) / 1e9);
                int tables = 10_000;
                t0 = System.nanoTime();
                for (int i = 0; i < tables; i++) {
                    m.dispatch(reply(i, Ids.SID_DATABASE, "", table));
                }
                SwingUtilities.invokeAndWait(() -> { });
                double tab = tables / ((System.nanoTime() - t0) / 1e9);
                System.out.printf("round %d: %.0f text replies/s to COM, %.0f table replies/s to DAB%n", round, text, tab);
                SwingUtilities.invokeAndWait(() -> assertThat(model.service(SVC).transcript()).hasSize(ServiceModel.MAX_LINES));
            }
        }
    }

    static OutgoingServerMessage reply(long id, String sid, String text, org.ripv.messages.Result r) {
        return new OutgoingServerMessage(new Header(id, new IdBadge("123456", "a"), List.of(), SVC, SVC + "TTY1",
                "SELECT", Priority.NORMAL, null), new Footer(sid, Status.OK, ErrorCode.NONE, List.of(), text, r));
    }
}
