package org.ripv.client.panels;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/** DAB's Export CSV and Export JSON write the tab's whole table with the writer the CLI's export uses. */
class DabExportTest {
    static final String DB = "<DatabaseServer>::<h>";
    final LinkedBlockingQueue<Runnable> ui = new LinkedBlockingQueue<>();
    final ClientModel model = new ClientModel();
    final GuiManager manager = new GuiManager(model, ui::add, (h, p) -> {
        throw new IOException("no network here");
    }, GuiManager.Timings.DEFAULT);
    long ids;

    @AfterEach
    void tearDown() {
        manager.close();
    }

    void dispatch(String body, String sid, String mailbox, Result result) {
        manager.dispatch(new OutgoingServerMessage(new Header(++ids, new IdBadge("123456", "a"), List.of(), "", mailbox, body,
                Priority.NORMAL, null), new Footer(sid, Status.OK, ErrorCode.NONE, List.of(), "", result)));
        for (Runnable r = ui.poll(); r != null; r = ui.poll()) {
            r.run();
        }
    }

    @Test
    void eachTabExportsAsCsvAndAsJsonWithNumbersAsNumbers() {
        dispatch("?services", Ids.FID_SERVICES, "", new ServiceList(List.of(new ServiceDescriptor(DB, Ids.SID_DATABASE, "",
                "DAB", List.of()))));
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(DB), manager);
        TableResult t = new TableResult("SELECT vehicle, lat FROM positions", List.of("VEHICLE", "LAT"),
                List.of("VARCHAR", "DOUBLE"), List.of(new String[] {"cp_388", "39.84772"}, new String[] {"x, \"y\"", null}), false);
        dispatch("SELECT vehicle, lat FROM positions", Ids.SID_DATABASE, DB + "TTY1", t);
        p.updateAll(model);
        assertThat(new String(p.dab().exported(0, false), StandardCharsets.UTF_8))
                .isEqualTo("VEHICLE,LAT\r\ncp_388,39.84772\r\n\"x, \"\"y\"\"\",\r\n");
        assertThat(new String(p.dab().exported(0, true), StandardCharsets.UTF_8)).isEqualTo(
                "{\"query\":\"SELECT vehicle, lat FROM positions\",\"columns\":[\"VEHICLE\",\"LAT\"],\"types\":[\"VARCHAR\",\"DOUBLE\"],"
                        + "\"truncated\":false,\"rows\":[{\"VEHICLE\":\"cp_388\",\"LAT\":39.84772},{\"VEHICLE\":\"x, \\\"y\\\"\",\"LAT\":null}]}\n");
        assertThat(PanelsTest.find(p, "exportJsonButton")).isNotNull();
    }
}
