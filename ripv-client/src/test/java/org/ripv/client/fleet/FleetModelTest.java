package org.ripv.client.fleet;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.SessionState;
import org.ripv.messages.TableResult;

class FleetModelTest {
    static final long T0 = FleetModel.time("2016-01-13 17:20:11.24");

    static TableResult latest(String[]... rows) {
        return new TableResult(FleetModel.LATEST_SQL, List.of("VEHICLE", "TIME_UTC", "LAT", "LON", "SOURCE"),
                List.of("VARCHAR", "TIMESTAMP", "DOUBLE", "DOUBLE", "VARCHAR"), List.of(rows), false);
    }

    @Test
    void oneRowPerVehicleFromTheDatabaseAndTheMailboxesGpsWinningAndTheNewerPositionKept() {
        List<String[]> recent = new ArrayList<>();
        for (int i = 0; i < 1000; i++) { // newest first
            recent.add(new String[] {"cp_388", "2016-01-13 17:20:11", Double.toString(39.8 - i * 0.001), Double.toString(-70.7 + i * 0.001)});
        }
        recent.add(new String[] {"unit_363", "2013-09-05 13:45:50", "50.1", "-144.9"});
        TableResult rec = new TableResult(FleetModel.RECENT_SQL, List.of("vehicle", "time_utc", "lat", "lon"),
                List.of("VARCHAR", "TIMESTAMP", "DOUBLE", "DOUBLE"), recent, true);
        FleetModel m = new FleetModel();
        m.update(List.of(
                        new MailboxStatus("<SerialPortServer>::<shore>CP_388", true, "", false, "",
                                new SessionState(SessionState.State.DIVED, T0 - 60_000, 41.0, -70.0, 3, null)),
                        new MailboxStatus("<SerialPortServer>::<shore>ru29", true, "", false, "",
                                new SessionState(SessionState.State.ON_CALL, T0, 41.63323, -70.53647, 1, null)),
                        new MailboxStatus("<SerialPortServer>::<shore>ttyV9", true, "", false, "",
                                new SessionState(SessionState.State.UNKNOWN, 0, null, null, 0, null)),
                        new MailboxStatus("<DatabaseServer>::<shore>TTY1", true, "", false, "")),
                latest(new String[] {"cp_388", "2016-01-13 17:20:11.24", "39.8", "-70.7", "dead-reckoned"},
                        new String[] {"cp_388", "2016-01-13 17:20:11.24", "39.84772", "-70.77226", "gps"},
                        new String[] {"unit_363", "2013-09-05 13:45:50.906", "50.1", "-144.9", "gps"}),
                rec, "");
        List<FleetModel.Vehicle> v = m.vehicles();
        assertThat(v).extracting(FleetModel.Vehicle::name).containsExactly("cp_388", "ru29", "ttyV9", "unit_363");
        FleetModel.Vehicle cp = v.get(0);
        assertThat(cp.source()).isEqualTo("gps");
        assertThat(cp.lat()).isEqualTo(39.84772);
        assertThat(cp.state()).isEqualTo("dived");
        assertThat(cp.mailbox()).isEqualTo("<SerialPortServer>::<shore>CP_388");
        assertThat(cp.fixTime()).isEqualTo(T0);
        assertThat(cp.trackLon()).hasSizeLessThanOrEqualTo(FleetModel.TRACK_POINTS).hasSizeGreaterThan(200);
        assertThat(cp.trackLat()[cp.trackLat().length - 1]).as("oldest first, the newest last").isEqualTo(39.8);
        FleetModel.Vehicle ru = v.get(1);
        assertThat(ru.source()).isEqualTo("console");
        assertThat(ru.lat()).isEqualTo(41.63323);
        assertThat(ru.state()).isEqualTo("on call");
        assertThat(v.get(2).hasFix()).isFalse();
        assertThat(v.get(3).mailbox()).isEmpty();
        assertThat(v.get(3).trackLon()).containsExactly(-144.9);
    }

    @Test
    void agesAndTimesReadForPeople() {
        assertThat(FleetModel.age(0, T0)).isEqualTo("no fix");
        assertThat(FleetModel.age(T0, T0 + 20_000)).isEqualTo("just now");
        assertThat(FleetModel.age(T0, T0 + 12 * 60_000)).isEqualTo("12 min ago");
        assertThat(FleetModel.age(T0, T0 + 185 * 60_000)).isEqualTo("3 h 05 min ago");
        assertThat(FleetModel.age(T0, T0 + 5L * 86_400_000)).isEqualTo("5 days ago");
        assertThat(FleetModel.time("2016-01-13T17:20:11Z")).isEqualTo(1452705611000L);
        assertThat(FleetModel.time("yesterday")).isZero();
    }

    @Test
    void withoutADatabaseTheMailboxesStillShow() {
        FleetModel m = new FleetModel();
        m.update(List.of(new MailboxStatus("<SerialPortServer>::<shore>ru29", true, "", false, "",
                new SessionState(SessionState.State.LOST, T0, 41.6, -70.5, 2, null))), null, null, "no DatabaseServer");
        assertThat(m.vehicles()).singleElement().satisfies(x -> {
            assertThat(x.state()).isEqualTo("lost");
            assertThat(x.trackLon()).isEmpty();
        });
        assertThat(m.problem()).isEqualTo("no DatabaseServer");
    }
}
