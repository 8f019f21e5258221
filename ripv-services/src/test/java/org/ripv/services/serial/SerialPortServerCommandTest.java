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
    void eachLinkMayOverrideTheSettingsForItself() {
        SerialPortServerCommand c = parse("--server", "h", "--baud", "115200", "--carrier", "ignore",
                "--link", "/dev/ttyUSB0,baud=9600,carrier=require,parity=odd,prompt=GLIDER>",
                "--link", "tcp://gw:4001,line-ending=lf,idle-timeout=250");
        LinkSettings radio = c.settings(c.links.get(0));
        assertEquals("/dev/ttyUSB0", radio.device());
        assertEquals("9600 8O1", radio.frameDescription());
        assertEquals(CarrierMode.REQUIRE, radio.carrier());
        assertTrue(radio.prompt().matcher("GLIDER>").find());
        LinkSettings tcp = c.settings(c.links.get(1));
        assertEquals("tcp://gw:4001", tcp.device());
        assertEquals("115200 8N1", tcp.frameDescription());
        assertEquals(CarrierMode.IGNORE, tcp.carrier());
        assertEquals("\n", tcp.lineEnding());
        assertEquals(250, tcp.idleTimeout().toMillis());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.settings("/dev/x,speed=9600"));
        assertTrue(e.getMessage().contains("unknown setting 'speed'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.settings("/dev/x,baud=fast"));
        assertTrue(e.getMessage().contains("'fast'"), e.getMessage());
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
