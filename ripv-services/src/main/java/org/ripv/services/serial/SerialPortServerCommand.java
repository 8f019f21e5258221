package org.ripv.services.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import org.ripv.files.PrivateFiles;
import org.ripv.patterns.UserPattern;
import org.ripv.security.AddressRanges;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.launch.Launchers;
import org.ripv.surfacing.CallInterval;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * Launches the SerialPortServer and registers it with a RIPVServer.
 *
 * <pre>
 * ripv service serial --server shore.example.org --link /tmp/ttyV0 --link tcp://localhost:2323 --baud 9600
 * java -jar ripv-services.jar SerialPortServer //shore.example.org     (the thesis form)
 * </pre>
 *
 * Exit codes: 0 stopped normally, 1 could not start, 2 bad options.
 */
@Command(name = "serial", mixinStandardHelpOptions = true, modelTransformer = LinkOptions.class,
        description = "Registers the SerialPortServer: one MailBox per serial port and per --link.")
public final class SerialPortServerCommand implements Callable<Integer> {

    @Mixin
    ServiceLaunchOptions launch;

    @Parameters(arity = "0..1", paramLabel = "//HOST", description = "The server, thesis style (same as --server HOST).")
    String thesisServer;

    @Option(names = "--link", paramLabel = "DEVICE|tcp://HOST:PORT|listen://[ADDR:]PORT",
            description = "A link to open besides the enumerated ports: a device path (ptys and symlinks too), tcp://host:port, "
                    + "or listen://[ADDR:]PORT where the vehicle (or its modem or RUDICS gateway) calls in; "
                    + "optionally followed by its own settings, e.g. /dev/ttyUSB0,baud=9600,carrier=require,name=ru29 "
                    + "(keys: baud, data-bits, parity, stop-bits, carrier, line-ending, prompt, prompt-regex, idle-timeout, "
                    + "command-timeout, send-command, receive-command, maxcommand, interrupt; name, surface, quiet, alert, line-length, "
                    + "rate, callers; keys, zmodem-send, zmodem-receive, to-vehicle). Repeatable.")
    List<String> links = new ArrayList<>();

    @Option(names = "--no-enumerate", description = "Do not open MailBoxes for the serial ports jSerialComm finds; only the --link ones.")
    boolean noEnumerate;

    @Option(names = "--reconnect", defaultValue = "2", paramLabel = "SECONDS",
            description = "How often a link that is down is retried (default ${DEFAULT-VALUE} s).")
    long reconnectSeconds;

    @Option(names = "--work", paramLabel = "DIR", description = "Where incoming files are assembled (default: a temporary directory).")
    Path workDir;

    @Spec
    CommandSpec spec;

    /**
     * Builds a link's settings: the command line's options, overridden by any {@code key=value}
     * pairs after the device ({@code --link /dev/ttyUSB0,baud=9600,carrier=require}).
     */
    LinkSettings settings(String spec) {
        LinkOptions.Link link = LinkOptions.Link.parse(spec);
        return settings(link, LinkOptions.values(this.spec, link));
    }

    private LinkSettings settings(LinkOptions.Link link, Map<String, String> o) {
        String ending = o.get("line-ending");
        String end = switch (ending.toLowerCase(Locale.ROOT)) {
            case "cr" -> "\r";
            case "lf" -> "\n";
            case "crlf" -> "\r\n";
            default -> throw new IllegalArgumentException("line ending '" + ending + "' is not cr, lf or crlf");
        };
        String carrierMode = o.get("carrier");
        CarrierMode mode = switch (carrierMode.toLowerCase(Locale.ROOT)) {
            case "require" -> CarrierMode.REQUIRE;
            case "ignore" -> CarrierMode.IGNORE;
            default -> throw new IllegalArgumentException("carrier '" + carrierMode + "' is not require or ignore");
        };
        String regex = o.get("prompt-regex");
        Pattern p = regex != null ? Pattern.compile(regex) : Pattern.compile(Pattern.quote(o.get("prompt")));
        return new LinkSettings(link.device(), number(o, "baud"), number(o, "data-bits"),
                LinkSettings.Parity.parse(o.get("parity")), LinkSettings.StopBits.parse(o.get("stop-bits")), end, p,
                Duration.ofMillis(number(o, "idle-timeout")), Duration.ofSeconds(number(o, "command-timeout")), mode,
                o.get("send-command"), o.get("receive-command"), Duration.ofSeconds(Math.max(1, reconnectSeconds)),
                YmodemConfig.lrzsz(), number(o, "maxcommand"), Interrupt.parse(o.get("interrupt")));
    }

    /** A link's settings and its call settings ({@code name=ru29,surface=...,quiet=600,alert=...}). */
    VehicleLink link(String spec) {
        LinkOptions.Link link = LinkOptions.Link.parse(spec);
        Map<String, String> o = LinkOptions.values(this.spec, link);
        LinkSettings settings = settings(link, o);
        try {
            return new VehicleLink(settings, new CallSettings(o.get("name"), regex(o.get("surface"), "surface"),
                    Duration.ofSeconds(number(o, "quiet")), regex(o.get("alert"), "alert"),
                    number(o, "line-length"), number(o, "rate"), callers(o.get("callers")),
                    o.containsKey("overdue") ? overdue(o.get("overdue")) : null),
                    new PilotSettings(ControlKey.parseList(o.get("keys")), o.get("zmodem-send"), o.get("zmodem-receive"),
                            ToVehicleMode.parse(o.get("to-vehicle"))));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--link '" + spec + "': " + e.getMessage(), e);
        }
    }

    private static Duration overdue(String spec) {
        try {
            return CallInterval.parse(spec);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("overdue: " + e.getMessage());
        }
    }

    private static AddressRanges callers(String spec) {
        try {
            return AddressRanges.parse(spec);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("callers: " + e.getMessage());
        }
    }

    /** surface= and alert= run on every vehicle line: linear time (RE2/J), issue 23 item 3. */
    private static com.google.re2j.Pattern regex(String re, String what) {
        return UserPattern.compile(what, re).pattern();
    }

    private static int number(Map<String, String> o, String key) {
        String v = o.get(key);
        try {
            return Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(key + " must be a whole number, got '" + v + "'");
        }
    }

    @Override
    public Integer call() throws Exception {
        if (thesisServer != null) {
            System.err.println("Error: the server is given twice ('--server' and '" + thesisServer + "'); give it once");
            return 2;
        }
        List<VehicleLink> linkSettings = new ArrayList<>();
        try {
            for (String link : links) {
                linkSettings.add(link(link));
            }
            if (links.isEmpty()) {
                settings("COM1"); // validates the options even when only enumerated ports are used
            }
        } catch (IllegalArgumentException e) {
            System.err.println("Error: " + e.getMessage());
            return 2;
        }
        Path work = workDir != null ? PrivateFiles.createDirectories(workDir)
                : Files.createTempDirectory("ripv-serial"); // createTempDirectory makes it 0700
        SerialPortServer server = SerialPortServer.withCalls(launch.hostName(), linkSettings, settings("COM1"),
                !noEnumerate, work);
        try {
            server.start();
        } catch (IOException | IllegalArgumentException e) {
            System.err.println("Error: " + e.getMessage());
            return 1;
        }
        StringBuilder listening = new StringBuilder();
        for (String h : server.handles()) {
            if (server.listenPort(h) >= 0) {
                listening.append(listening.isEmpty() ? "; waiting for calls: " : ", ").append(h).append(" on port ")
                        .append(server.listenPort(h));
            }
        }
        System.out.println("SerialPortServer " + server.name() + " MailBoxes: " + server.handles() + listening);
        return launch.serve(server);
    }

    public static void main(String[] args) {
        System.exit(Launchers.commandLine(new SerialPortServerCommand()).execute(ServiceLaunchOptions.thesisForm(args)));
    }
}
