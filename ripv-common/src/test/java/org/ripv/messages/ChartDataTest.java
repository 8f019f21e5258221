package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ChartDataTest {
    @Test
    void boundsAreCheckedWhoeverBuildsIt() {
        double[] big = new double[ChartData.MAX_POINTS_PER_SERIES + 1];
        assertThatThrownBy(() -> new ChartData.Series("s", "m", big, big)).hasMessageContaining("at most");
        assertThatThrownBy(() -> new ChartData.Series("s", "m", new double[2], new double[3])).hasMessageContaining("2 x but 3 y");
        double[] full = new double[ChartData.MAX_POINTS_PER_SERIES];
        List<ChartData.Series> many = new ArrayList<>();
        for (int i = 0; i <= ChartData.MAX_POINTS / full.length; i++) {
            many.add(new ChartData.Series("s" + i, "", full, full));
        }
        assertThatThrownBy(() -> new ChartData(ChartData.Kind.XY, "", "", "", many, null, 0, true))
                .hasMessageContaining("points; at most " + ChartData.MAX_POINTS);
        ChartData c = new ChartData(ChartData.Kind.TRACK, "x".repeat(500), null, null, List.of(), null, 0, false);
        assertThat(c.title()).hasSize(ChartData.MAX_TEXT);
        assertThat(c.xLabel()).isEmpty();
        assertThat(new ImageResult("a.jpg", new byte[0]).chart()).isNull();
    }
}
