package org.ripv.services.simulator;

import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.launch.Launchers;
import org.ripv.launch.OptionChecks;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * Runs the glider simulator on a TCP port or a serial device / pseudo-terminal.
 *
 * <pre>
 * ripv simulator --listen 2323
 * socat pty,raw,echo=0,link=/tmp/ttyV0 pty,raw,echo=0,link=/tmp/ttyV1 &amp;
 * ripv simulator --tty /tmp/ttyV1        # and the SerialPortServer opens --link /tmp/ttyV0
 * ripv simulator --call localhost:2323 --dive-seconds 30 --surface-seconds 45 --name ru29
 *                                        # calls --link listen://2323,name=ru29
 * ripv simulator --call localhost:2323 --dialog gliderdos --baud 2400 --latency 1s --drop-after 60s
 *                                        # a Slocum's surface dialog and GliderDOS over an Iridium-like call
 * </pre>
 *
 * Exit codes: 0 stopped, 1 could not start, 2 bad options.
 */
@Command(name = "simulator", mixinStandardHelpOptions = true,
        description = "A PicoDOS-like glider: dir, type, del, ys, yr, zs, zr, GO (submerge); on a port, a tty, or calling in;"
                + " with --dialog gliderdos a Slocum's surface dialog, control keys and GliderDOS.")
public final class SimulatorCommand implements Callable<Integer> {

    static final class Where {
        @Option(names = "--listen", paramLabel = "PORT", description = "Serve TCP connections on PORT (default 2323).")
        Integer port;

        @Option(names = "--tty", paramLabel = "PATH", description = "Serve a serial device or pseudo-terminal.")
        String tty;

        @Option(names = "--call", paramLabel = "HOST:PORT",
                description = "Call a SerialPortServer's listen:// link like a glider: surface dialog, commands, hang up, dive, call again.")
        String call;
    }

    @ArgGroup(exclusive = true, multiplicity = "0..1")
    Where where;

    @Option(names = "--dir", paramLabel = "DIR", description = "The glider's files (default: a temporary directory with sample logs).")
    Path dir;

    @Option(names = "--files", paramLabel = "DIR", description = "Copy DIR's files (e.g. Slocum .mrg/DBA files) onto the glider at start.")
    Path seedFiles;

    @Option(names = "--bind", paramLabel = "ADDRESS",
            description = "Listen on this address only (default 127.0.0.1: this machine; 0.0.0.0 for every interface).")
    String bind;

    @Option(names = "--submerge-seconds", defaultValue = "30", description = "How long GO keeps it under water (default ${DEFAULT-VALUE}).")
    long submergeSeconds;

    @Option(names = "--dive-seconds", defaultValue = "60", paramLabel = "N",
            description = "With --call: how long each dive lasts, between calls (default ${DEFAULT-VALUE}).")
    long diveSeconds;

    @Option(names = "--surface-seconds", defaultValue = "60", paramLabel = "M",
            description = "With --call: how long each call lasts (default ${DEFAULT-VALUE}); a command under way finishes first.")
    long surfaceSeconds;

    @Option(names = "--name", defaultValue = "sim01", paramLabel = "NAME",
            description = "The vehicle's name in its surface dialog (default ${DEFAULT-VALUE}).")
    String name;

    /** What the glider says when a call begins. */
    enum Dialog { picodos, gliderdos }

    @Option(names = "--dialog", defaultValue = "picodos", paramLabel = "picodos|gliderdos",
            description = "picodos (default): the C:\\> prompt at once. gliderdos: a Slocum's surface dialog, the keys"
                    + " (Ctrl-C GliderDOS, Ctrl-R resume, Ctrl-E extend, Ctrl-F re-read) and a countdown of"
                    + " --surface-seconds that resumes the mission if nobody answers.")
    Dialog dialog;

    @Option(names = "--minute-seconds", defaultValue = "60", paramLabel = "S",
            description = "With --dialog gliderdos: how long a 'callback' minute lasts (default ${DEFAULT-VALUE}; less to rehearse quickly).")
    long minuteSeconds;

    @Option(names = "--abort-on-call", split = ",", paramLabel = "N[,N...]",
            description = "With --dialog gliderdos: these calls (1 for the first) surface because of an abort"
                    + " (MS_ABORT_OVERDEPTH), which its ABORT HISTORY then shows.")
    List<Integer> abortCalls = List.of();

    @Option(names = "--leak-from-call", defaultValue = "0", paramLabel = "N",
            description = "With --dialog gliderdos: from call N on its aft leak detector reads 1.21 V, a leak (default: never).")
    int leakFrom;

    @Option(names = "--baud", defaultValue = "0", paramLabel = "BAUD",
            description = "On TCP: pace the call to BAUD each way, 10 bits a byte (e.g. 2400, Iridium's rate; default: unpaced).")
    int baud;

    @Option(names = "--latency", paramLabel = "TIME", description = "On TCP: delay every byte each way by TIME (e.g. 1s, 500ms).")
    String latency;

    @Option(names = "--drop-after", paramLabel = "TIME|BYTESb",
            description = "On TCP: drop each call after TIME (60s, 2m) or after BYTES crossed both ways (40000b); a caller dials again 2 s later.")
    String dropAfter;

    /** The Iridium-like line the options ask for; throws with the bad value quoted. */
    IridiumLine.Settings line() {
        if (baud < 0 || baud > 10_000_000) {
            throw new IllegalArgumentException("--baud " + baud + " must be between 1 and 10000000 (0: unpaced)");
        }
        Duration l = latency == null ? Duration.ZERO : IridiumLine.Settings.duration("--latency", latency);
        if (l.compareTo(Duration.ofMinutes(1)) > 0) {
            throw new IllegalArgumentException("--latency '" + latency + "' is over a minute");
        }
        return IridiumLine.Settings.withDrop(baud, l, dropAfter);
    }

    /** Refuses what picocli cannot see: ranges and options that go together; the message quotes the bad value. */
    IridiumLine.Settings check() {
        OptionChecks.atLeast("--dive-seconds", diveSeconds, 1);
        OptionChecks.atLeast("--surface-seconds", surfaceSeconds, 1);
        if (!name.matches("[A-Za-z0-9._-]{1,64}")) {
            throw new IllegalArgumentException("--name '" + name + "' must be 1-64 letters, digits, '.', '_' or '-'");
        }
        IridiumLine.Settings line = line();
        if (leakFrom < 0 || abortCalls.stream().anyMatch(n -> n == null || n < 1)) {
            throw new IllegalArgumentException("--abort-on-call and --leak-from-call take call numbers from 1");
        }
        if (dialog != Dialog.gliderdos && (leakFrom > 0 || !abortCalls.isEmpty())) {
            throw new IllegalArgumentException("--abort-on-call and --leak-from-call need --dialog gliderdos");
        }
        OptionChecks.atLeast("--minute-seconds", minuteSeconds, 1);
        if (line.any() && where != null && where.tty != null) {
            throw new IllegalArgumentException("--baud, --latency and --drop-after are for TCP (--listen, --call);"
                    + " a tty has its own line");
        }
        return line;
    }

    /** {@code --call HOST:PORT} as host and port, or null without {@code --call}. */
    String[] callTarget() {
        if (where == null || where.call == null) {
            return null;
        }
        int colon = where.call.lastIndexOf(':');
        if (colon <= 0 || !where.call.substring(colon + 1).matches("\\d{1,5}")
                || Integer.parseInt(where.call.substring(colon + 1)) > 65535) {
            throw new IllegalArgumentException("--call '" + where.call + "' is not HOST:PORT");
        }
        return new String[] {where.call.substring(0, colon), where.call.substring(colon + 1)};
    }

    @Override
    public Integer call() throws Exception {
        IridiumLine.Settings line;
        String[] target;
        try {
            line = check();
            target = callTarget();
        } catch (IllegalArgumentException e) {
            System.err.println("Error: " + e.getMessage());
            return 2;
        }
        Path files = dir != null ? dir : Files.createTempDirectory("ripv-glider");
        try (GliderSimulator sim = new GliderSimulator(files, Duration.ofSeconds(submergeSeconds), YmodemConfig.lrzsz())) {
            sim.overLine(line).named(name);
            if (dialog == Dialog.gliderdos) {
                sim.speakGliderDos(Duration.ofSeconds(surfaceSeconds), Duration.ofSeconds(minuteSeconds))
                        .trouble(Set.copyOf(abortCalls), leakFrom);
            }
            if (seedFiles != null) {
                try (var list = Files.list(seedFiles)) {
                    for (Path f : list.filter(Files::isRegularFile).toList()) {
                        Files.copy(f, files.resolve(f.getFileName().toString()), StandardCopyOption.REPLACE_EXISTING);
                    }
                }
            }
            if (target != null) {
                sim.call(target[0], Integer.parseInt(target[1]), name, Duration.ofSeconds(diveSeconds),
                        Duration.ofSeconds(surfaceSeconds));
                System.out.println("glider simulator " + name + " calls " + where.call + " for " + surfaceSeconds
                        + " s every " + (diveSeconds + surfaceSeconds) + " s, files in " + files);
            } else if (where != null && where.tty != null) {
                sim.attach(where.tty);
                System.out.println("glider simulator on " + where.tty + ", files in " + files);
            } else {
                sim.bindTo(bind == null ? InetAddress.getLoopbackAddress() : InetAddress.getByName(bind));
                int port = sim.listen(where != null && where.port != null ? where.port : 2323);
                System.out.println("glider simulator on tcp://localhost:" + port + ", files in " + files);
            }
            sim.await();
        }
        return 0;
    }

    public static void main(String[] args) {
        System.exit(Launchers.commandLine(new SimulatorCommand()).execute(args));
    }
}
