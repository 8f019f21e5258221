package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class VisCommandTest {

    @Test
    void parsesFileAndQuotedOptions() {
        VisCommand c = VisCommand.parse("vis:glider-temperature.dat title=\"Dive 3, we03\" legend=\"a | b\" size=640x480 out=dive3");
        assertThat(c.file()).isEqualTo("glider-temperature.dat");
        assertThat(c.output()).isEqualTo("dive3");
        assertThat(c.labels().title()).isEqualTo("Dive 3, we03");
        assertThat(c.labels().legend()).containsExactly("a", "b");
        assertThat(c.labels().width()).isEqualTo(640);
        assertThat(c.labels().xLabel()).isNull();
    }

    @Test
    void defaultOutputIsTheFilesBaseName() {
        assertThat(VisCommand.parse("VIS: \"my data.v2.dat\"").output()).isEqualTo("my_data_v2");
        assertThat(VisCommand.parse("vis:glider.temp.dat").output()).isEqualTo("glider_temp");
        assertThat(VisCommand.parse("vis:...dat").output()).isEqualTo("plot");
    }

    @Test
    void badOptionsAreExplained() {
        assertThatThrownBy(() -> VisCommand.parse("vis:")).hasMessageContaining("needs a data file");
        assertThatThrownBy(() -> VisCommand.parse("vis:a.dat colour=red")).hasMessageContaining("unknown option 'colour'");
        assertThatThrownBy(() -> VisCommand.parse("vis:a.dat out=../../etc/x")).hasMessageContaining("not a usable name");
        assertThatThrownBy(() -> VisCommand.parse("vis:a.dat size=big")).hasMessageContaining("WIDTHxHEIGHT");
        assertThatThrownBy(() -> VisCommand.parse("vis:a.dat size=10x10")).hasMessageContaining("outside");
        assertThatThrownBy(() -> VisCommand.parse("vis:a.dat title=\"open")).hasMessageContaining("not closed");
    }
}
