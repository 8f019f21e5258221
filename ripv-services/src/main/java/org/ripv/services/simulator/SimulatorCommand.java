package org.ripv.services.simulator;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.launch.Launchers;
import picocli.CommandLine;
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
 * </pre>
 *
 * Exit codes: 0 stopped, 1 could not start, 2 bad options.
 */
@Command(name = "simulator", mixinStandardHelpOptions = true,
        description = "A PicoDOS-like glider: dir, type, del, ys, yr, GO (submerge).")
public final class SimulatorCommand implements Callable<Integer> {

    static final class Where {
        @Option(names = "--listen", paramLabel = "PORT", description = "Serve TCP connections on PORT (default 2323).")
        Integer port;

        @Option(names = "--tty", paramLabel = "PATH", description = "Serve a serial device or pseudo-terminal.")
        String tty;
    }

    @ArgGroup(exclusive = true, multiplicity = "0..1")
    Where where;

    @Option(names = "--dir", paramLabel = "DIR", description = "The glider's files (default: a temporary directory with sample logs).")
    Path dir;

    @Option(names = "--files", paramLabel = "DIR", description = "Copy DIR's files (e.g. Slocum .mrg/DBA files) onto the glider at start.")
    Path seedFiles;

    @Option(names = "--submerge-seconds", defaultValue = "30", description = "How long GO keeps it under water (default ${DEFAULT-VALUE}).")
    long submergeSeconds;

    @Override
    public Integer call() throws Exception {
        Path files = dir != null ? dir : Files.createTempDirectory("ripv-glider");
        try (GliderSimulator sim = new GliderSimulator(files, Duration.ofSeconds(submergeSeconds), YmodemConfig.lrzsz())) {
            if (seedFiles != null) {
                try (var list = Files.list(seedFiles)) {
                    for (Path f : list.filter(Files::isRegularFile).toList()) {
                        Files.copy(f, files.resolve(f.getFileName().toString()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                    }
                }
            }
            if (where != null && where.tty != null) {
                sim.attach(where.tty);
                System.out.println("glider simulator on " + where.tty + ", files in " + files);
            } else {
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
