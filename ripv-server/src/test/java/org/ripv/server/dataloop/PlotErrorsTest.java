package org.ripv.server.dataloop;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.ripv.messages.Ids;

/** The plot errors that say what to do: a vis: typo lists the plot commands, no data yet says how to get it. */
class PlotErrorsTest {
    static final String NO_FILE = "no file 'trak' in the upload directory; upload it first (?ulfiles lists them)";

    @Test
    void aVisWordThatIsNeitherAPlotNorAFileListsThePlotCommands() {
        String e = DataLoop.noSuchFile(Ids.SID_DATAVIS, "vis:trak sim01", NO_FILE);
        assertThat(e).startsWith("'vis:trak' is not a plot command (did you mean vis:track?) and there is no file 'trak' in the upload directory");
        assertThat(e).contains("vis:track VEHICLE", "vis:depth VEHICLE", "vis:profile VEHICLE SENSOR", "vis:sql SELECT",
                "vis:file NAME", "vis:NAME (a data file in the upload directory)");
        assertThat(DataLoop.noSuchFile(Ids.SID_DATAVIS, "VIS:dpeth sim01", NO_FILE)).contains("(did you mean vis:depth?)");
        assertThat(DataLoop.noSuchFile(Ids.SID_DATAVIS, "vis:salinity.dat", NO_FILE))
                .startsWith("'vis:salinity.dat' is not a plot command and there is no file");
    }

    @Test
    void otherServicesAndVisFileKeepTheFileError() {
        assertThat(DataLoop.noSuchFile(Ids.SID_SERIAL, "vis:trak sim01", NO_FILE)).isEqualTo(NO_FILE);
        assertThat(DataLoop.noSuchFile(Ids.SID_DATAVIS, "vis:file x.dba x=a y=b", NO_FILE)).isEqualTo(NO_FILE);
        assertThat(DataLoop.noSuchFile(Ids.SID_DATAVIS, "ymodem:put trak", NO_FILE)).isEqualTo(NO_FILE);
    }

    @Test
    void aMissingTableIsNoDataYetOtherFailuresAreNot() {
        assertThat(PlotRequests.noSchemaYet("Table/View 'POSITIONS' does not exist. (SQLState 42X05)")).isTrue();
        assertThat(PlotRequests.noSchemaYet("relation \"positions\" does not exist (SQLState 42P01)")).isTrue();
        assertThat(PlotRequests.noSchemaYet("Syntax error (SQLState 42X01)")).isFalse();
    }

    @Test
    void typosAreOneEditAway() {
        assertThat(Typos.near("trak", "track")).isTrue();
        assertThat(Typos.near("tarck", "track")).isTrue();
        assertThat(Typos.near("trackk", "track")).isTrue();
        assertThat(Typos.near("trxck", "track")).isTrue();
        assertThat(Typos.near("tk", "track")).isFalse();
        assertThat(Typos.near("depth", "track")).isFalse();
    }
}
