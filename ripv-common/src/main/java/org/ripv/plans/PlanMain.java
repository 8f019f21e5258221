package org.ripv.plans;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.ripv.launch.Launchers;

import org.ripv.launch.Version;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code ripv plan check FILE...}: reads Slocum behaviour files offline as the glider would and
 * prints each one's waypoints and b_args, or its problems as {@code FILE:LINE: reason} on
 * standard error. Exit codes: 0 every file passed, 1 a file was refused or could not be read,
 * 2 a bad command line.
 */
@Command(name = "ripv plan", mixinStandardHelpOptions = true, versionProvider = Version.Provider.class,
        description = "Slocum behaviour files (.ma) read as the glider reads them (docs/plans.md).",
        subcommands = {PlanMain.Check.class, PlanMain.ForecastCommand.class},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:every file passed", "1:a file was refused (FILE:LINE: reason on standard error) or unreadable",
                "2:a bad command line"})
public final class PlanMain implements Callable<Integer> {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }

    public static void main(String[] args) {
        System.exit(run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true)));
    }

    /** The whole command, output injected (tests call this). */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        CommandLine cl = Launchers.commandLine(new PlanMain(), "ripv plan");
        cl.setOut(out);
        cl.setErr(err);
        return cl.execute(args);
    }

    /** What each subcommand shares: -h and -V, the exit codes' heading, and its own command line for output and errors. */
    @Command(mixinStandardHelpOptions = true, exitCodeListHeading = "%nExit codes:%n")
    abstract static class Subcommand implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;
    }

    @Command(name = "forecast",
            description = "Distance, bearing and ETA from a position to each waypoint of a goto FILE, in the order the glider flies it.",
            exitCodeList = {"0:the forecast", "1:the file was refused or unreadable", "2:a bad command line"})
    static final class ForecastCommand extends Subcommand {
        @Parameters(paramLabel = "FILE", description = "a goto file (goto_l10.ma)")
        Path file;

        @Option(names = "--from", required = true, paramLabel = "LAT,LON", description = "where the glider is, decimal degrees")
        String from;

        @Option(names = "--speed", paramLabel = "M/S", defaultValue = "0.3",
                description = "its speed through the water (default: ${DEFAULT-VALUE} m/s)")
        double speed;

        @Option(names = "--current", paramLabel = "EAST,NORTH", defaultValue = "0,0",
                description = "the depth-averaged current, m/s (default: none)")
        String current;

        @Override
        public Integer call() throws IOException {
            double[] at = pair(from, "--from", 90, 180);
            double[] cur = pair(current, "--current", 10, 10);
            if (!(speed > 0) || speed > 5) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--speed: over 0 and at most 5 m/s, not " + speed);
            }
            String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
            PlanCheck c;
            try (InputStream in = Files.newInputStream(file)) {
                c = BehaviorFileReader.check(name, in, PlanLimits.DEFAULT);
            }
            if (!c.ok()) {
                spec.commandLine().getErr().println(c.problemText());
                return 1;
            }
            if (!c.file().isGoto()) {
                spec.commandLine().getErr().println("Error: " + name + " is a " + c.file().behavior() + " file: no waypoints");
                return 1;
            }
            List<Forecast.Leg> legs = Forecast.legs(c.file(), at[0], at[1], Instant.now(), speed, cur[0], cur[1]);
            spec.commandLine().getOut().println(Forecast.render(legs, String.format(Locale.ROOT,
                    "of %s from %.5f, %.5f at %.3f m/s, current %.3f east %.3f north", name, at[0], at[1], speed, cur[0], cur[1])));
            return 0;
        }

        private double[] pair(String text, String option, double maxA, double maxB) {
            String[] p = text.split(",");
            try {
                double a = Double.parseDouble(p[0].trim());
                double b = Double.parseDouble(p[1].trim());
                if (p.length == 2 && Math.abs(a) <= maxA && Math.abs(b) <= maxB) {
                    return new double[] {a, b};
                }
            } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
                // refused below
            }
            throw new CommandLine.ParameterException(spec.commandLine(), option + ": two numbers A,B within ±" + (int) maxA
                    + ", ±" + (int) maxB + ", not '" + text + "'");
        }
    }

    @Command(name = "check",
            description = "Check FILE(s): the waypoint table and b_args, or each problem as FILE:LINE: reason.",
            exitCodeList = {"0:every file passed", "1:a file was refused or unreadable", "2:a bad command line"})
    static final class Check extends Subcommand {
        @Parameters(arity = "1..*", paramLabel = "FILE", description = "behaviour files: goto_l10.ma, surfac06.ma, yo10.ma, …")
        List<Path> files;

        @Option(names = "--max-waypoints", paramLabel = "N", defaultValue = "" + PlanLimits.FIRMWARE_WAYPOINTS,
                description = "the most waypoints the glider's firmware takes (default: ${DEFAULT-VALUE}, masterdata's goto_list)")
        int maxWaypoints;

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            PlanLimits limits;
            try {
                limits = PlanLimits.DEFAULT.withMaxWaypoints(maxWaypoints);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--max-waypoints: " + e.getMessage());
            }
            int status = 0;
            for (Path p : files) {
                String name = p.getFileName() == null ? p.toString() : p.getFileName().toString();
                PlanCheck c;
                try (InputStream in = Files.newInputStream(p)) {
                    c = BehaviorFileReader.check(name, in, limits);
                } catch (IOException e) {
                    err.println("Error: cannot read " + p + ": " + e.getMessage());
                    status = 1;
                    continue;
                }
                if (c.ok()) {
                    out.println(PlanTable.render(c.file()));
                } else {
                    err.println(c.problemText());
                    err.println(name + ": refused, " + c.problems().size() + " problem(s)");
                    status = 1;
                }
                out.flush();
                err.flush();
            }
            return status;
        }
    }
}
