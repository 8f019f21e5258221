package org.ripv.server.dataloop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.TableResult;

/** Parsing of the plots from data, the table-to-data-file conversion, and the ingest settings. */
class PlotRequestsTest {
    private final PlotRequests plots = new PlotRequests(null, () -> "<DatabaseServer>::<h>TTY1");

    @Test
    void namedPlotsBecomeQueriesWithTheVehicleInside() {
        PlotRequests.Plan p = plots.parse("vis:track cp_388 since=2016-01-13T17:00:00Z");
        assertThat(p.kind()).isEqualTo("track");
        assertThat(p.output()).isEqualTo("track-cp_388");
        // first the newest fix for the mark, then the points up to it (newest first, so a row limit keeps the newest)
        assertThat(p.sql()).isEqualTo("SELECT time_utc, source FROM positions WHERE vehicle = 'cp_388'"
                + " AND time_utc >= CAST('2016-01-13 17:00:00' AS TIMESTAMP) ORDER BY time_utc DESC FETCH FIRST 1 ROWS ONLY");
        assertThat(PlotRequests.trackPointsSql("cp_388", p.since(), "2016-01-13 17:20:11.24094")).isEqualTo(
                "SELECT lon, lat FROM positions WHERE vehicle = 'cp_388' AND time_utc >= CAST('2016-01-13 17:00:00' AS TIMESTAMP)"
                + " AND time_utc <= CAST('2016-01-13 17:20:11.24094' AS TIMESTAMP) ORDER BY time_utc DESC");
        assertThatThrownBy(() -> PlotRequests.trackPointsSql("cp_388", null, "x' OR '1'='1")).hasMessageContaining("not a time");
        assertThat(p.labels()).contains("plot: track");
        assertThat(plots.parse("vis:depth unit_363 db=<DatabaseServer>::<other>TTY2").database())
                .isEqualTo("<DatabaseServer>::<other>TTY2");
        assertThat(plots.parse("vis:profile unit_363 sci_water_temp out=p1").output()).isEqualTo("p1");
        assertThat(plots.parse("vis:sql SELECT a, b FROM t WHERE c = 'x=y'").sql()).isEqualTo("SELECT a, b FROM t WHERE c = 'x=y'");
    }

    @Test
    void badRequestsAreRefusedWithAReason() {
        assertThatThrownBy(() -> plots.parse("vis:track x';DROP")).hasMessageContaining("is not a vehicle name");
        assertThatThrownBy(() -> plots.parse("vis:track a b")).hasMessageStartingWith("usage: vis:track VEHICLE");
        assertThatThrownBy(() -> plots.parse("vis:profile v s'--")).hasMessageContaining("is not a sensor name");
        assertThatThrownBy(() -> plots.parse("vis:track v since=yesterday")).hasMessageContaining("is not an ISO time");
        assertThatThrownBy(() -> plots.parse("vis:track v colour=red")).hasMessageContaining("unknown option 'colour'");
        assertThatThrownBy(() -> plots.parse("vis:sql")).hasMessageStartingWith("usage: vis:sql");
        assertThat(PlotRequests.sqlTime("2016-01-13")).isEqualTo("2016-01-13 00:00:00");
        assertThat(PlotRequests.sqlTime("2016-01-13T18:00:00+01:00")).isEqualTo("2016-01-13 17:00:00");
    }

    @Test
    void tablesBecomeNumbers() {
        TableResult t = new TableResult("q", List.of("T", "V", "S"), List.of("TIMESTAMP", "DOUBLE", "VARCHAR"),
                List.of(new String[] {"2016-01-13 17:20:11.24094", "1.5", "x"}, new String[] {"1970-01-01 00:00:01.0", null, null}),
                false);
        assertThat(TableData.number(t.rows().get(0)[0], "TIMESTAMP", "T")).isEqualTo(1452705611.24094, org.assertj.core.api.Assertions.within(1e-6));
        assertThat(TableData.token(t.rows().get(0)[0], "TIMESTAMP", "T")).isEqualTo("1452705611.24094");
        assertThat(TableData.token("1969-12-31 23:59:58.25", "TIMESTAMP", "T")).isEqualTo("-1.75");
        assertThat(TableData.token("1970-01-01 00:00:01.0", "TIMESTAMP", "T")).isEqualTo("1");
        assertThat(TableData.number(null, "DOUBLE", "V")).isNaN();
        // the database's decimal text passes as it is; infinities and NaN become the data file's words
        assertThat(TableData.token("-144.56061666666668", "DOUBLE", "V")).isEqualTo("-144.56061666666668");
        assertThat(TableData.token("1.0E-5", "DOUBLE", "V")).isEqualTo("1.0E-5");
        assertThat(TableData.token("Infinity", "DOUBLE", "V")).isEqualTo("Inf");
        assertThat(TableData.token("-Infinity", "DOUBLE PRECISION", "V")).isEqualTo("-Inf");
        assertThat(TableData.token("NaN", "DOUBLE", "V")).isEqualTo("NaN");
        for (String bad : new String[] {"1.2.3", "1e", "--1", "0x10", "1d", ".", "-", "1 2", "1e5x"}) {
            assertThatThrownBy(() -> TableData.token(bad, "VARCHAR", "S")).as(bad).hasMessageContaining("not a number");
        }
        assertThatThrownBy(() -> TableData.tokens(t)).hasMessageContaining("column S (VARCHAR) holds 'x', not a number");
        String data = new String(TableData.write(List.of("plot: time"), List.of(new String[] {"1", "NaN"},
                new String[] {"2.5", "3"})), StandardCharsets.UTF_8);
        assertThat(data).isEqualTo("% plot: time\n1 NaN\n2.5 3\n");
    }

    @Test
    void dbaFilesAreRecognisedByTheirFirstLine() {
        assertThat(DataLoop.isDba("dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\r\nencoding_ver: 2\r\n".getBytes())).isTrue();
        assertThat(DataLoop.isDba("dbd_label: DBD_ASC(dinkum_binary_data_ascii)fileX\n".getBytes())).isFalse();
        assertThat(DataLoop.isDba("MISSION1.LOG".getBytes())).isFalse();
        assertThat(DataLoop.vehicle("dbd_label: x\nfilename: cp_388-2016-012-0-0\n".getBytes())).isEqualTo("cp_388");
    }

    @Test
    void ingestSettingsPerVehicleAndLink(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("ingest.properties");
        IngestSettings s = new IngestSettings(f);
        assertThat(s.enabled("cp_388", "TTY1")).isTrue();
        Files.writeString(f, "vehicle.cp_388 = off\nlink.TTY2 = off\n");
        assertThat(s.enabled("cp_388", "TTY1")).isFalse();
        assertThat(s.enabled("unit_363", "TTY2")).isFalse();
        assertThat(s.enabled("unit_363", "TTY1")).isTrue();
        Files.writeString(f, "auto = off\nvehicle.unit_363 = on\ndatabase = <DatabaseServer>::<h>TTY2\n# changed\n");
        assertThat(s.enabled("cp_388", "TTY1")).isFalse();
        assertThat(s.enabled("unit_363", "TTY1")).isTrue();
        assertThat(s.database()).isEqualTo("<DatabaseServer>::<h>TTY2");
    }
}
