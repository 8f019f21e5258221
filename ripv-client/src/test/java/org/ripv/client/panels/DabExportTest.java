package org.ripv.client.panels;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Ids;
import org.ripv.messages.TableResult;

/** DAB's Export CSV and Export JSON write the tab's whole table with the writer the CLI's export uses. */
class DabExportTest extends PanelsTest {
    @Test
    void eachTabExportsAsCsvAndAsJsonWithNumbersAsNumbers() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(DB), manager);
        TableResult t = new TableResult("SELECT vehicle, lat FROM positions", List.of("VEHICLE", "LAT"),
                List.of("VARCHAR", "DOUBLE"), List.of(new String[] {"cp_388", "39.84772"}, new String[] {"x, \"y\"", null}), false);
        dispatch("SELECT vehicle, lat FROM positions", Ids.SID_DATABASE, DB + "TTY1", "", t);
        p.updateAll(model);
        assertThat(new String(p.dab().exported(0, false), StandardCharsets.UTF_8))
                .isEqualTo("VEHICLE,LAT\r\ncp_388,39.84772\r\n\"x, \"\"y\"\"\",\r\n");
        assertThat(new String(p.dab().exported(0, true), StandardCharsets.UTF_8)).isEqualTo(
                "{\"query\":\"SELECT vehicle, lat FROM positions\",\"columns\":[\"VEHICLE\",\"LAT\"],\"types\":[\"VARCHAR\",\"DOUBLE\"],"
                        + "\"truncated\":false,\"rows\":[{\"VEHICLE\":\"cp_388\",\"LAT\":39.84772},{\"VEHICLE\":\"x, \\\"y\\\"\",\"LAT\":null}]}\n");
        assertThat(find(p, "exportJsonButton")).isNotNull();
    }
}
