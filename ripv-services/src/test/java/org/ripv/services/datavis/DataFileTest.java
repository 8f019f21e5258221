package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

class DataFileTest {

    private static String normalize(String text, PlotLabels overrides) throws Exception {
        StringWriter out = new StringWriter();
        DataFile.normalize(text.getBytes(StandardCharsets.UTF_8), overrides, out);
        return out.toString();
    }

    @Test
    void labelsGoFirstAndRowsAreCanonical() throws Exception {
        String in = "% mission 12, glider we03\n"
                + "%title: Temperature\n"
                + "1   20.5\t19.0\n"
                + "% legend: surface | 10 m\n"
                + "2 20.7 19.1 % a trailing remark\n"
                + "% XLABEL : time (s)\n"
                + "%  ylabel: T (°C)\n";
        assertThat(normalize(in, PlotLabels.NONE)).isEqualTo(
                "% title: Temperature\n% xlabel: time (s)\n% ylabel: T (°C)\n% legend: surface | 10 m\n"
                        + "1 20.5 19.0\n2 20.7 19.1\n");
    }

    @Test
    void nanInfEmptyFieldsAndBlankLinesAreGaps() throws Exception {
        String in = "1,2,3\n2,,nan\n\n\n3,Inf,-inf\n4,NaN,5\n\n";
        assertThat(normalize(in, PlotLabels.NONE)).isEqualTo(
                "1 2 3\n2 NaN NaN\nNaN NaN NaN\n3 Inf -Inf\n4 NaN 5\n");
    }

    @Test
    void optionsOverrideTheFilesLabels() throws Exception {
        String in = "% title: old\n% legend: a\n1 2\n";
        String out = normalize(in, new PlotLabels("new", null, "depth", List.of("b"), 1024, 768));
        assertThat(out).isEqualTo("% title: new\n% ylabel: depth\n% legend: b\n% size: 1024x768\n1 2\n");
    }

    @Test
    void textInANumericColumnNamesTheLineAndColumn() {
        assertThatThrownBy(() -> normalize("% t\n1 2\n3 four\n", PlotLabels.NONE))
                .isInstanceOf(DataFormatException.class)
                .hasMessageContaining("line 3")
                .hasMessageContaining("column 2")
                .hasMessageContaining("'four'");
        assertThatThrownBy(() -> normalize("1 2d\n", PlotLabels.NONE)).hasMessageContaining("line 1").hasMessageContaining("'2d'");
        assertThatThrownBy(() -> normalize("1 0x1p3\n", PlotLabels.NONE)).hasMessageContaining("'0x1p3'");
    }

    @Test
    void raggedRowsNameTheLine() {
        assertThatThrownBy(() -> normalize("1 2 3\n4 5 6\n\n7 8\n", PlotLabels.NONE))
                .isInstanceOf(DataFormatException.class)
                .hasMessageContaining("line 4")
                .hasMessageContaining("ragged")
                .hasMessageContaining("2 values where the rows before have 3");
    }

    @Test
    void emptyFilesAndCommentOnlyFilesAreRefused() {
        assertThatThrownBy(() -> normalize("", PlotLabels.NONE)).hasMessageContaining("empty");
        assertThatThrownBy(() -> normalize("% title: nothing\n\n", PlotLabels.NONE)).hasMessageContaining("no data rows");
    }

    @Test
    void aLegendLongerThanTheSeriesIsRefused() {
        assertThatThrownBy(() -> normalize("% legend: a|b|c\n1 2 3\n", PlotLabels.NONE))
                .hasMessageContaining("legend names 3 series but the file has 2");
    }

    @Test
    void badSizeLineNamesTheLine() {
        assertThatThrownBy(() -> normalize("1 2\n% size: huge\n", PlotLabels.NONE))
                .hasMessageContaining("line 2").hasMessageContaining("WIDTHxHEIGHT");
    }

    @Test
    void legendSplitsOnBarsElseCommas() {
        assertThat(PlotLabels.splitLegend("a, b | c")).containsExactly("a, b", "c");
        assertThat(PlotLabels.splitLegend("a, b")).containsExactly("a", "b");
    }

    @Test
    void parseCountsRowsAndColumnsAndStreams() throws Exception {
        long[] sum = {0};
        DataFile.Summary s = DataFile.parse(DataFile.reader("\uFEFF1 2\n3 4\n".getBytes(StandardCharsets.UTF_8)),
                (v, t) -> sum[0] += (long) (v[0] + v[1]));
        assertThat(s.columns()).isEqualTo(2);
        assertThat(s.rows()).isEqualTo(2);
        assertThat(sum[0]).isEqualTo(10);
    }

    @Test
    void checkingAcceptsAndRefusesExactlyWhatParsingDoes() throws Exception {
        String[] fields = {"0", "-12.5", "+3", ".5", "5.", "1e5", "1.5E-3", "-2e+10", "1e400", "-1e400", "NaN", "na", "Inf",
            "+inf", "-INF", "1d", "0x10", "1.2.3", "--1", "-", ".", "e5", "1e", "1e5x", "Infinity", "-NaN", "12:00", "abc"};
        for (String f : fields) {
            String file = "1 " + f + "\n";
            String[] parsed = tokens(file, false);
            String[] checked = tokens(file, true);
            assertThat(checked).as(f).isEqualTo(parsed);
        }
        assertThat(tokens("1 1e400\n", true)).containsExactly("1", "Inf");
        assertThat(tokens("1 -12.5\n", true)).containsExactly("1", "-12.5");
        assertThat(tokens("1 5d\n", true)).containsExactly("refused: line 1: column 2: '5d' is not a number (use NaN, or leave"
                + " the field empty, for a gap)");
    }

    /** The tokens of a one-row file's row, or why it was refused. */
    private static String[] tokens(String file, boolean check) throws Exception {
        String[][] row = {null};
        DataFile.RowSink sink = (v, t) -> row[0] = t.clone();
        try {
            if (check) {
                DataFile.check(DataFile.reader(file.getBytes(StandardCharsets.UTF_8)), sink);
            } else {
                DataFile.parse(DataFile.reader(file.getBytes(StandardCharsets.UTF_8)), sink);
            }
            return row[0];
        } catch (DataFormatException e) {
            return new String[] {"refused: " + e.getMessage()};
        }
    }
}
