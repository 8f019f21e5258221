package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** The to-vehicle option of a link, and reading the vehicle's listing that decides whether a file was sent. */
class ToVehicleCommandsTest {
    static final String DIR = """
             Volume in drive C is GLIDER
             Directory of C:\\

            goto_l10.ma       20000  11-26-26  18:30
            NIGHT.MI             42  11-26-26  18:29
                    2 file(s)        20042 bytes
            """;

    @Test
    void theListingGivesTheSizeOfTheFileByItsNameInAnyCase() {
        assertThat(ToVehicleCommands.sizeOf(DIR, "goto_l10.ma")).isEqualTo(20000L);
        assertThat(ToVehicleCommands.sizeOf(DIR, "night.mi")).isEqualTo(42L);
        assertThat(ToVehicleCommands.sizeOf(DIR, "BLOCKED.MI")).isNull();
        assertThat(ToVehicleCommands.sizeOf(DIR, "file(s)")).isNull();
    }

    @Test
    void aLinkSendsNothingUnlessToVehicleIsSet() {
        assertThat(PilotSettings.defaults().toVehicle()).isEqualTo(ToVehicleMode.OFF);
        assertThat(ToVehicleMode.parse("ZMODEM")).isEqualTo(ToVehicleMode.ZMODEM);
        assertThat(ToVehicleMode.parse("ymodem")).isEqualTo(ToVehicleMode.YMODEM);
        assertThatThrownBy(() -> ToVehicleMode.parse("kermit")).hasMessageContaining("'kermit'");
        SerialPortServerCommand c = new SerialPortServerCommand();
        picocli.CommandLine cl = new picocli.CommandLine(c);
        cl.parseArgs("--server", "h", "--link", "/tmp/x");
        assertThat(c.link("listen://127.0.0.1:0,name=ru29,to-vehicle=zmodem").pilot().toVehicle()).isEqualTo(ToVehicleMode.ZMODEM);
        assertThat(c.link("listen://127.0.0.1:0,name=ru29").pilot().toVehicle()).isEqualTo(ToVehicleMode.OFF);
        assertThatThrownBy(() -> c.link("listen://127.0.0.1:0,to-vehicle=kermit")).hasMessageContaining("to-vehicle 'kermit'");
        assertThatThrownBy(() -> new ToVehicleCommands(PilotSettings.defaults(), null, null, null).requireOn())
                .hasMessageContaining("to-vehicle=zmodem");
    }
}
