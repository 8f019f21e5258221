package org.ripv.plans;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import org.ripv.launch.Launchers;

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
@Command(name = "ripv plan", mixinStandardHelpOptions = true, versionProvider = org.ripv.launch.Version.Provider.class,
        description = "Slocum behaviour files (.ma) read as the glider reads them (docs/plans.md).",
        subcommands = PlanMain.Check.class,
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

    @Command(name = "check", mixinStandardHelpOptions = true,
            description = "Check FILE(s): the waypoint table and b_args, or each problem as FILE:LINE: reason.",
            exitCodeListHeading = "%nExit codes:%n",
            exitCodeList = {"0:every file passed", "1:a file was refused or unreadable", "2:a bad command line"})
    static final class Check implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

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
