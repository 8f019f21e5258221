package org.ripv.services.serial;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import org.junit.jupiter.api.parallel.Isolated;

/** The launcher's options turn into link settings; bad values are refused with the value quoted. */
@Isolated // replaces System.err for a while: another class's output would land in it
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
    void keysAndZmodemCommandsPerLink() {
        SerialPortServerCommand c = parse("--server", "h", "--link", "/dev/ttyUSB0",
                "--link", "/dev/ttyUSB1,keys=ctrl-c,Ctrl-R,zmodem-send=lsz -q,zmodem-receive=lrz -y,name=ru29",
                "--link", "/dev/ttyUSB2,keys=none");
        PilotSettings d = c.link(c.links.get(0)).pilot();
        assertEquals("ctrl-c, ctrl-r, ctrl-e, ctrl-f", ControlKey.describe(d.keys()));
        assertEquals("zs", d.zmodemSend());
        assertEquals("zr", d.zmodemReceive());
        PilotSettings ru29 = c.link(c.links.get(1)).pilot();
        assertEquals("ctrl-c, ctrl-r", ControlKey.describe(ru29.keys()));
        assertEquals((byte) 0x12, ru29.keys().get(1).code());
        assertEquals("lsz -q A.DBD B.DBD", ru29.sendCommand(java.util.List.of("A.DBD", "B.DBD")));
        assertEquals("lrz -y", ru29.zmodemReceive());
        assertEquals("none", ControlKey.describe(c.link(c.links.get(2)).pilot().keys()));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.link("/dev/x,keys=ctrl-c,esc"));
        assertTrue(e.getMessage().contains("'esc' is not a control key"), e.getMessage());
    }

    @Test
    void theInterruptIsCtrlCUnlessALinkSaysOtherwise() {
        SerialPortServerCommand c = parse("--server", "h", "--link", "/dev/ttyUSB0", "--link", "/dev/ttyUSB1,interrupt=^X^C",
                "--link", "/dev/ttyUSB2,interrupt=none");
        assertEquals("\u0003", c.settings(c.links.get(0)).interrupt());
        assertEquals("\u0018\u0003", c.settings(c.links.get(1)).interrupt());
        assertEquals("", c.settings(c.links.get(2)).interrupt());
        assertEquals("", parse("--server", "h", "--interrupt", "none").settings("COM1").interrupt());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.settings("/dev/x,interrupt=^1"));
        assertTrue(e.getMessage().contains("not a control key"), e.getMessage());
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

    @Test
    void linksTakeANameAndCallSettingsAndListenLinksAreNamedAfterTheirPort() {
        SerialPortServerCommand c = parse("--server", "h", "--quiet", "300", "--rate", "50",
                "--link", "listen://2323,name=ru29,quiet=60,alert=leak|LEAK,line-length=200",
                "--link", "listen://127.0.0.1:2324", "--link", "tcp://gw:4001,surface=AT SURFACE");
        VehicleLink ru29 = c.link(c.links.get(0));
        assertEquals("ru29", ru29.handle());
        assertTrue(ru29.isListen());
        assertEquals("listen://2323", ru29.settings().device());
        assertEquals(60, ru29.call().quiet().toSeconds());
        assertEquals(200, ru29.call().lineLength());
        assertEquals(50, ru29.call().linesPerSecond());
        assertTrue(ru29.call().alert().matcher("hull LEAK").find());
        assertEquals("127.0.0.1", VehicleLink.listenUri("listen://2323").getHost());
        assertEquals("0.0.0.0", VehicleLink.listenUri("listen://0.0.0.0:2323").getHost());
        VehicleLink anonymous = c.link(c.links.get(1));
        assertEquals("listen-2324", anonymous.handle());
        assertEquals(300, anonymous.call().quiet().toSeconds());
        assertEquals("127.0.0.1", VehicleLink.listenUri(anonymous.settings().device()).getHost());
        VehicleLink tcp = c.link(c.links.get(2));
        assertEquals("tcp-gw-4001", tcp.handle());
        assertTrue(tcp.call().surface().matcher("GLIDER AT SURFACE").find());
        assertTrue(CallSettings.defaults().surface().matcher("Glider ru29 at surface.").find());
        // the default alert= leaves a Slocum's every-surfacing text alone; the server reads aborts from the dialog
        for (String routine : List.of("Hit Control-C within 50 seconds to abort the mission...",
                "Hit Control-R to RESUME the mission, or Control-C to abort it", "ABORT HISTORY: last abort cause: MS_ABORT_OVERDEPTH",
                "   sensor:m_leakdetect_voltage(volts)=2.47   2.4 secs ago", "devices:(t/m/s) errs:     0/  0/  0")) {
            assertFalse(CallSettings.defaults().alert().matcher(routine).find(), routine);
        }
        for (String trouble : List.of("LEAK detected in aft hull", "leak detected", "ERROR: pitch motor", "Error: no GPS")) {
            assertTrue(CallSettings.defaults().alert().matcher(trouble).find(), trouble);
        }
        assertTrue(anonymous.call().callers().isEmpty());
    }

    @Test
    void callersLimitWhoMayCallAListenLink() throws Exception {
        SerialPortServerCommand c = parse("--server", "h", "--callers", "10.1.0.0/16",
                "--link", "listen://0.0.0.0:2323,name=ru29,callers=192.0.2.7,2001:db8::/32", "--link", "listen://2324");
        VehicleLink ru29 = c.link(c.links.get(0));
        assertTrue(ru29.call().callers().contains(java.net.InetAddress.getByName("192.0.2.7")));
        assertTrue(ru29.call().callers().contains(java.net.InetAddress.getByName("2001:db8::5")));
        assertFalse(ru29.call().callers().contains(java.net.InetAddress.getByName("10.1.2.3")));
        VehicleLink other = c.link(c.links.get(1));
        assertTrue(other.call().callers().contains(java.net.InetAddress.getByName("10.1.2.3")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> c.link("listen://2325,callers=gateway.example.org"));
        assertTrue(e.getMessage().contains("callers") && e.getMessage().contains("'gateway.example.org'"), e.getMessage());
    }

    @Test
    void badCallSettingsAreQuoted() {
        SerialPortServerCommand c = parse("--server", "h");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,name=ru 29"));
        assertTrue(e.getMessage().contains("'ru 29'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,name=../x"));
        assertTrue(e.getMessage().contains("'../x'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,alert=(unclosed"));
        assertTrue(e.getMessage().contains("'(unclosed'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,quiet=0"));
        assertTrue(e.getMessage().contains("quiet"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,line-length=5"));
        assertTrue(e.getMessage().contains("line length 5"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://host:"));
        assertTrue(e.getMessage().contains("listen://[ADDR:]PORT"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> c.link("listen://2323,volume=11"));
        assertTrue(e.getMessage().contains("unknown setting 'volume'") && e.getMessage().contains("name"), e.getMessage());
    }

    @Test
    void aListenPortInUseStopsTheLauncherWithTheAddress() throws Exception {
        try (java.net.ServerSocket taken = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
            java.io.PrintStream old = System.err;
            System.setErr(new java.io.PrintStream(err, true, java.nio.charset.StandardCharsets.UTF_8));
            int code;
            try {
                code = new CommandLine(new SerialPortServerCommand()).execute("--server", "127.0.0.1:1", "--no-enumerate",
                        "--work", System.getProperty("java.io.tmpdir") + "/ripv-serial-cmd-test",
                        "--link", "listen://127.0.0.1:" + taken.getLocalPort() + ",name=ru29");
            } finally {
                System.setErr(old);
            }
            assertEquals(1, code, err.toString());
            assertTrue(err.toString().contains("cannot listen on 127.0.0.1:" + taken.getLocalPort() + " for ru29"),
                    err.toString());
        }
    }
}
