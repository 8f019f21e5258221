package org.ripv.export;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.TableResult;

class TableExportTest {
    private final TableResult t = new TableResult("SELECT ...", List.of("VEHICLE", "LAT", "N", "NOTE", "TIME_UTC"),
            List.of("VARCHAR", "DOUBLE", "INTEGER", "VARCHAR", "TIMESTAMP"),
            List.of(new String[] {"cp_388", "39.84772", "2", "a \"quoted\", comma", "2016-01-13 17:20:11.24094"},
                    new String[] {"unit_363", null, "-1", null, null}), false);

    @Test
    void jsonHasNumbersAsNumbersAndNullAsNull() {
        assertThat(TableExport.json(t)).isEqualTo("{\"query\":\"SELECT ...\",\"columns\":[\"VEHICLE\",\"LAT\",\"N\",\"NOTE\","
                + "\"TIME_UTC\"],\"types\":[\"VARCHAR\",\"DOUBLE\",\"INTEGER\",\"VARCHAR\",\"TIMESTAMP\"],\"truncated\":false,"
                + "\"rows\":[{\"VEHICLE\":\"cp_388\",\"LAT\":39.84772,\"N\":2,\"NOTE\":\"a \\\"quoted\\\", comma\","
                + "\"TIME_UTC\":\"2016-01-13 17:20:11.24094\"},{\"VEHICLE\":\"unit_363\",\"LAT\":null,\"N\":-1,\"NOTE\":null,"
                + "\"TIME_UTC\":null}]}\n");
    }

    @Test
    void csvQuotesWhatNeedsItAndLeavesNullEmpty() {
        assertThat(TableExport.csv(t)).isEqualTo("VEHICLE,LAT,N,NOTE,TIME_UTC\r\n"
                + "cp_388,39.84772,2,\"a \"\"quoted\"\", comma\",2016-01-13 17:20:11.24094\r\n"
                + "unit_363,,-1,,\r\n");
    }
}
