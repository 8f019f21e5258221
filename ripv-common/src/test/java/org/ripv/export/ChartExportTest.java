package org.ripv.export;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ChartData;

class ChartExportTest {
    private final ChartData depth = new ChartData(ChartData.Kind.DEPTH, "depth of cp_388", "time (UTC)", "depth (m)",
            List.of(new ChartData.Series("m_depth", "m", new double[] {1452700000_000.0, 1452700060_000.0, 1452700120_000.0},
                    new double[] {0, Double.NaN, 12.25})), null, 3, false);

    @Test
    void csvHasOneLinePerPointWithTheTimeInIsoAndAGapEmpty() {
        assertThat(ChartExport.csv(depth)).isEqualTo("series,unit,x,time_utc,y\r\n"
                + "m_depth,m,1452700000000,2016-01-13T15:46:40Z,0\r\n"
                + "m_depth,m,1452700060000,2016-01-13T15:47:40Z,\r\n"
                + "m_depth,m,1452700120000,2016-01-13T15:48:40Z,12.25\r\n");
    }

    @Test
    void jsonHasNumbersAsNumbersAGapAsNullAndTheNewestFix() {
        assertThat(ChartExport.json(depth)).isEqualTo("{\"title\":\"depth of cp_388\",\"kind\":\"depth\",\"xLabel\":\"time (UTC)\","
                + "\"yLabel\":\"depth (m)\",\"xIsEpochMillis\":true,\"yInverted\":true,\"rows\":3,\"reduced\":false,"
                + "\"series\":[{\"name\":\"m_depth\",\"unit\":\"m\",\"x\":[1452700000000,1452700060000,1452700120000],"
                + "\"y\":[0,null,12.25]}]}\n");
        ChartData track = new ChartData(ChartData.Kind.TRACK, "track", "lon", "lat",
                List.of(new ChartData.Series("positions", "", new double[] {-70.5}, new double[] {41.25})),
                new ChartData.Mark(-70.5, 41.25, "newest fix"), 1, false);
        assertThat(ChartExport.json(track)).contains("\"newest\":{\"x\":-70.5,\"y\":41.25,\"label\":\"newest fix\"}");
        assertThat(ChartExport.csv(track)).isEqualTo("series,unit,x,y\r\npositions,\"\",-70.5,41.25\r\n");
    }
}
