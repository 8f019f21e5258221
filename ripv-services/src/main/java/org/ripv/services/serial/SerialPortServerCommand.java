package org.ripv.services.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import org.ripv.files.PrivateFiles;
import org.ripv.patterns.UserPattern;
import org.ripv.security.AddressRanges;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.launch.Launchers;
import org.ripv.surfacing.CallInterval;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

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
@Command(name = "serial", mixinStandardHelpOptions = true,
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

    @Option(names = "--baud", defaultValue = "115200", description = "Baud rate (default ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--data-bits", defaultValue = "8", description = "Data bits 5-8 (default ${DEFAULT-VALUE}).")
    int dataBits;

    @Option(names = "--parity", defaultValue = "none", description = "none, odd, even, mark or space (default ${DEFAULT-VALUE}).")
    String parity;

    @Option(names = "--stop-bits", defaultValue = "1", description = "1, 1.5 or 2 (default ${DEFAULT-VALUE}).")
    String stopBits;

    @Option(names = "--carrier", defaultValue = "ignore",
            description = "require: send nothing while DCD is low and report the MailBox not available; ignore (ptys, TCP). Default ${DEFAULT-VALUE}.")
    String carrier;

    @Option(names = "--line-ending", defaultValue = "crlf", description = "cr, lf or crlf after each command (default ${DEFAULT-VALUE}).")
    String lineEnding;

    @Option(names = "--prompt", defaultValue = LinkSettings.DEFAULT_PROMPT,
            description = "The vehicle's prompt, literally (default ${DEFAULT-VALUE}).")
    String prompt;

    @Option(names = "--prompt-regex", description = "The vehicle's prompt as a Java regular expression (instead of --prompt).")
    String promptRegex;

    @Option(names = "--idle-timeout", defaultValue = "2000", paramLabel = "MILLIS",
            description = "A reply ends after this much silence if no prompt came (default ${DEFAULT-VALUE} ms).")
    long idleMillis;

    @Option(names = "--command-timeout", defaultValue = "60", paramLabel = "SECONDS",
            description = "The longest a plain command may run (default ${DEFAULT-VALUE} s).")
    long commandSeconds;

    @Option(names = "--send-command", defaultValue = "ys", description = "The vehicle's YMODEM send command, given the names (default ${DEFAULT-VALUE}).")
    String sendCommand;

    @Option(names = "--receive-command", defaultValue = "yr", description = "The vehicle's YMODEM receive command (default ${DEFAULT-VALUE}).")
    String receiveCommand;

    @Option(names = "--reconnect", defaultValue = "2", paramLabel = "SECONDS",
            description = "How often a link that is down is retried (default ${DEFAULT-VALUE} s).")
    long reconnectSeconds;

    @Option(names = "--max-command", defaultValue = "1024", paramLabel = "CHARS",
            description = "The longest command written to a link (per link: maxcommand=N); longer ones are refused"
                    + " (default ${DEFAULT-VALUE}, at most 16384).")
    int maxCommand;

    @Option(names = "--surface", defaultValue = CallSettings.DEFAULT_SURFACE, paramLabel = "REGEX",
            description = "On links with neither carrier nor caller: output that marks a call's start (default ${DEFAULT-VALUE}).")
    String surface;

    @Option(names = "--quiet", defaultValue = "600", paramLabel = "SECONDS",
            description = "On those links: silence this long ends the call, DIVED (default ${DEFAULT-VALUE} s).")
    long quietSeconds;

    @Option(names = "--alert", defaultValue = CallSettings.DEFAULT_ALERT, paramLabel = "REGEX",
            description = "Output lines that raise an ALERT event (default ${DEFAULT-VALUE}).")
    String alert;

    @Option(names = "--line-length", defaultValue = "1024", paramLabel = "CHARS",
            description = "Console lines are cut at this length (default ${DEFAULT-VALUE}).")
    int lineLength;

    @Option(names = "--rate", defaultValue = "200", paramLabel = "LINES",
            description = "Console lines per second per link; the excess is marked 'N lines skipped' (default ${DEFAULT-VALUE}).")
    int rate;

    @Option(names = "--interrupt", defaultValue = "^C", paramLabel = "KEYS",
            description = "What ?cancel writes to stop a running vehicle command: ^C, \\x03, text, or none"
                    + " (per link: interrupt=; default ${DEFAULT-VALUE}).")
    String interrupt;

    @Option(names = "--keys", defaultValue = ControlKey.DEFAULT_KEYS, paramLabel = "KEY[,KEY...]",
            description = "The control keys ?key may press on a vehicle, ctrl-a … ctrl-z, or none"
                    + " (per link: keys=; default ${DEFAULT-VALUE}).")
    String keys;

    @Option(names = "--zmodem-send", defaultValue = "zs", paramLabel = "COMMAND",
            description = "The vehicle's ZMODEM send command, given the names (per link: zmodem-send=; default ${DEFAULT-VALUE}).")
    String zmodemSend;

    @Option(names = "--zmodem-receive", defaultValue = "zr", paramLabel = "COMMAND",
            description = "The vehicle's ZMODEM receive command (per link: zmodem-receive=; default ${DEFAULT-VALUE}).")
    String zmodemReceive;

    @Option(names = "--callers", paramLabel = "CIDR[,CIDR...]",
            description = "On listen:// links: take calls only from these addresses, e.g. the RUDICS gateway's "
                    + "(per link: callers=...; default: anyone who can reach the port).")
    String callers;

    @Option(names = "--work", paramLabel = "DIR", description = "Where incoming files are assembled (default: a temporary directory).")
    Path workDir;

    /** The keys a {@code --link} may override for itself, after its device: {@code DEVICE,baud=9600,...}. */
    static final Set<String> LINK_KEYS = Set.of("baud", "data-bits", "parity", "stop-bits", "carrier",
            "line-ending", "prompt", "prompt-regex", "idle-timeout", "command-timeout", "send-command", "receive-command",
            "maxcommand", "interrupt");

    /**
     * Builds a link's settings: the command line's options, overridden by any {@code key=value}
     * pairs after the device ({@code --link /dev/ttyUSB0,baud=9600,carrier=require}).
     */
    LinkSettings settings(String spec) {
        String[] parts = spec.split(",(?=[a-z-]+=)");
        String device = parts[0];
        Map<String, String> o = new HashMap<>();
        for (int i = 1; i < parts.length; i++) {
            String key = parts[i].substring(0, parts[i].indexOf('='));
            if (!LINK_KEYS.contains(key) && !CALL_KEYS.contains(key) && !PILOT_KEYS.contains(key)) {
                Set<String> all = new TreeSet<>(LINK_KEYS);
                all.addAll(CALL_KEYS);
                all.addAll(PILOT_KEYS);
                throw new IllegalArgumentException("--link '" + spec + "': unknown setting '" + key + "'; a link may set "
                        + all);
            }
            o.put(key, parts[i].substring(key.length() + 1));
        }
        String ending = o.getOrDefault("line-ending", lineEnding);
        String end = switch (ending.toLowerCase(Locale.ROOT)) {
            case "cr" -> "\r";
            case "lf" -> "\n";
            case "crlf" -> "\r\n";
            default -> throw new IllegalArgumentException("line ending '" + ending + "' is not cr, lf or crlf");
        };
        String carrierMode = o.getOrDefault("carrier", carrier);
        CarrierMode mode = switch (carrierMode.toLowerCase(Locale.ROOT)) {
            case "require" -> CarrierMode.REQUIRE;
            case "ignore" -> CarrierMode.IGNORE;
            default -> throw new IllegalArgumentException("carrier '" + carrierMode + "' is not require or ignore");
        };
        String regex = o.getOrDefault("prompt-regex", o.containsKey("prompt") ? null : promptRegex);
        Pattern p = regex != null ? Pattern.compile(regex) : Pattern.compile(Pattern.quote(o.getOrDefault("prompt", prompt)));
        return new LinkSettings(device, number(o, "baud", baud), (int) number(o, "data-bits", dataBits),
                LinkSettings.Parity.parse(o.getOrDefault("parity", parity)),
                LinkSettings.StopBits.parse(o.getOrDefault("stop-bits", stopBits)), end, p,
                Duration.ofMillis(number(o, "idle-timeout", idleMillis)),
                Duration.ofSeconds(number(o, "command-timeout", commandSeconds)), mode,
                o.getOrDefault("send-command", sendCommand), o.getOrDefault("receive-command", receiveCommand),
                Duration.ofSeconds(Math.max(1, reconnectSeconds)), YmodemConfig.lrzsz(), number(o, "maxcommand", maxCommand),
                Interrupt.parse(o.getOrDefault("interrupt", interrupt)));
    }

    /** The keys of a link's call and console settings ({@link CallSettings}). */
    static final Set<String> CALL_KEYS = Set.of("name", "surface", "quiet", "alert", "line-length",
            "rate", "callers", "overdue");

    /** The keys of a link's {@link PilotSettings}: control keys and ZMODEM commands. */
    static final Set<String> PILOT_KEYS = Set.of("keys", "zmodem-send", "zmodem-receive",
            "to-vehicle");

    /** A link's settings and its call settings ({@code name=ru29,surface=...,quiet=600,alert=...}). */
    VehicleLink link(String spec) {
        LinkSettings link = settings(spec);
        String[] parts = spec.split(",(?=[a-z-]+=)");
        Map<String, String> o = new HashMap<>();
        for (int i = 1; i < parts.length; i++) {
            String key = parts[i].substring(0, parts[i].indexOf('='));
            o.put(key, parts[i].substring(key.length() + 1));
        }
        try {
            return new VehicleLink(link, new CallSettings(o.get("name"), regex(o.getOrDefault("surface", surface), "surface"),
                    Duration.ofSeconds(number(o, "quiet", quietSeconds)), regex(o.getOrDefault("alert", alert), "alert"),
                    number(o, "line-length", lineLength), number(o, "rate", rate),
                    callers(o.getOrDefault("callers", callers)),
                    o.containsKey("overdue") ? overdue(o.get("overdue")) : null),
                    new PilotSettings(ControlKey.parseList(o.getOrDefault("keys", keys)),
                            o.getOrDefault("zmodem-send", zmodemSend), o.getOrDefault("zmodem-receive", zmodemReceive),
                            ToVehicleMode.parse(o.getOrDefault("to-vehicle", "off"))));
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

    private static int number(Map<String, String> o, String key, long fallback) {
        String v = o.get(key);
        if (v == null) {
            return (int) fallback;
        }
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
