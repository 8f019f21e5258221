package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** The launcher's options turn into link settings; bad values are refused with the value quoted. */
class SerialPortServerCommandTest {

    private static SerialPortServerCommand parse(String... args) {
        SerialPortServerCommand c = new SerialPortServerCommand();
        new CommandLine(c).parseArgs(org.ripv.service.ServiceLaunchOptions.thesisForm(args));
        return c;
    }

    @Test
    void thesisFormBecomesServerOption() {
        assertArrayEquals(new String[] {"--server", "deslab.mit.edu"},
                org.ripv.service.ServiceLaunchOptions.thesisForm(new String[] {"//deslab.mit.edu"}));
        assertArrayEquals(new String[] {"--server", "a", "//b"},
                org.ripv.service.ServiceLaunchOptions.thesisForm(new String[] {"--server", "a", "//b"}));
    }

    @Test
    void optionsMakeSettings() {
        SerialPortServerCommand c = parse("--server", "h", "--link", "/tmp/ttyV0", "--link", "tcp://gw:4001",
                "--baud", "9600", "--parity", "even", "--data-bits", "7", "--stop-bits", "2", "--carrier", "require",
                "--line-ending", "cr", "--prompt", "GLIDER>", "--idle-timeout", "500", "--send-command", "zs",
                "--receive-command", "zr");
        LinkSettings s = c.settings("/tmp/ttyV0");
        assertEquals(9600, s.baud());
        assertEquals("9600 7E2", s.frameDescription());
        assertEquals(CarrierMode.REQUIRE, s.carrier());
        assertEquals("\r", s.lineEnding());
        assertTrue(s.prompt().matcher("x GLIDER>").find());
        assertEquals(500, s.idleTimeout().toMillis());
        assertEquals("zs", s.sendCommand());
        assertEquals("zr", s.receiveCommand());
        assertEquals(2, c.links.size());
    }

    @Test
    void defaultsArePicoDos() {
        LinkSettings s = parse("--server", "h").settings("COM1");
        assertEquals("115200 8N1", s.frameDescription());
        assertTrue(s.prompt().matcher("C:\\>").find());
        assertEquals("\r\n", s.lineEnding());
        assertEquals(CarrierMode.IGNORE, s.carrier());
    }

    @Test
    void badValuesAreQuoted() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> parse("--server", "h", "--parity", "sometimes").settings("x"));
        assertTrue(e.getMessage().contains("'sometimes'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> parse("--server", "h", "--carrier", "maybe").settings("x"));
        assertTrue(e.getMessage().contains("'maybe'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> parse("--server", "h", "--baud", "7").settings("x"));
        assertTrue(e.getMessage().contains("7"), e.getMessage());
    }
}
