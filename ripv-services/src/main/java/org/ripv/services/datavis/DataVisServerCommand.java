package org.ripv.services.datavis;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.launch.Launchers;
import org.ripv.launch.OptionChecks;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * Launches a DataVisServer and keeps it registered with a RIPVServer:
 * <pre>
 * ripv service datavis --server HOST[:REGPORT] [--secret-file F] [--workdir DIR]
 *                      [--worker builtin|octave|none] [--timeout SECONDS] [--octave PATH] [--script ripvOut.m]
 * DataVisServer //HOST              (the thesis's form)
 * </pre>
 * Exit codes: 0 stopped normally, 1 could not start (e.g. Octave missing), 2 usage error.
 */
@Command(name = "datavis", mixinStandardHelpOptions = true,
        description = "Runs the DataVisServer: vis:NAME plots a data file from the server's upload directory to JPEG.")
public final class DataVisServerCommand implements Callable<Integer> {
    @Mixin
    ServiceLaunchOptions launch;

    @Parameters(arity = "0..1", paramLabel = "//HOST", description = "The server, thesis style (same as --server).")
    String positionalServer;

    @Option(names = "--workdir", paramLabel = "DIR", description = "The file exchange directory (default: ~/.ripv/datavis).")
    Path workDir;

    @Option(names = "--worker", paramLabel = "MODE", defaultValue = "builtin",
            description = "builtin (JFreeChart, default), octave (octave-cli on ripvOut.m, started and restarted here), "
                    + "or none (a worker started by hand in the work directory).")
    String worker;

    @Option(names = "--timeout", paramLabel = "SECONDS", defaultValue = "60",
            description = "How long a plot may take before the request fails (default 60).")
    long timeoutSeconds;

    @Option(names = "--octave", paramLabel = "PATH", defaultValue = "octave-cli",
            description = "The Octave program for --worker octave (default octave-cli).")
    String octave;

    @Option(names = "--script", paramLabel = "FILE", description = "The ripvOut.m to run (default: the copy in the jar).")
    Path script;

    @Spec
    CommandLine.Model.CommandSpec spec;

    /** The options as a service configuration. */
    DataVisServer.Config config() {
        Path dir = workDir != null ? workDir : Path.of(System.getProperty("user.home"), ".ripv", "datavis");
        WorkerMode mode;
        try {
            OptionChecks.atLeast("--timeout", timeoutSeconds, 1);
            mode = WorkerMode.parse(worker);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        return new DataVisServer.Config(dir, mode, Duration.ofSeconds(timeoutSeconds), octave, script);
    }

    @Override
    public Integer call() throws Exception {
        if (positionalServer != null) {
            launch.server(positionalServer);
        }
        DataVisServer.Config config = config();
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        DataVisServer service = new DataVisServer(launch.hostName(), config);
        PrintWriter out = spec.commandLine().getOut();
        try {
            service.start();
        } catch (Exception e) {
            spec.commandLine().getErr().println("Error: cannot start the DataVisServer: " + e.getMessage()
                    + (config.worker() == WorkerMode.OCTAVE ? " (is Octave installed? try --octave PATH or --worker builtin)" : ""));
            service.stop();
            return 1;
        }
        out.println(service.name() + " running: worker " + config.worker() + ", work directory " + service.workDir()
                + "; registering with the server");
        out.flush();
        return launch.serve(service);
    }

    /** Parses and runs; returns the exit code. */
    public static int run(String... args) {
        return Launchers.commandLine(new DataVisServerCommand()).execute(ServiceLaunchOptions.thesisForm(args));
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }
}
