package org.ripv.dac;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.ripv.services.ingest.SensorListCache;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code ripv dac profiles|check}: a glider's files to IOOS Glider DAC profile files, and the
 * DAC's checks on such files (docs/dac.md). Exit codes: 0 done, 1 input refused or a file that
 * fails the check, 2 a usage error.
 */
@Command(name = "dac", mixinStandardHelpOptions = true, subcommands = {DacCommand.Profiles.class, DacCommand.Check.class, DacCommand.Push.class},
        description = "IOOS Glider DAC profile files (NetCDF-3, template IOOS_Glider_NetCDF_v2.0) with QARTOD flags.")
public final class DacCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }

    /** What each subcommand shares: -h and -V, and its own command line for output and errors. */
    @Command(mixinStandardHelpOptions = true)
    abstract static class Subcommand implements Callable<Integer> {
        @Spec
        CommandSpec spec;
    }

    @Command(name = "profiles",
            description = {"Writes one file per dive and per climb: glider_yyyymmddTHHMMSSZ_rt.nc from .sbd/.tbd (a call's files),"
                    + " _delayed.nc from .dbd/.ebd, each checked as the DAC's checker would.",
                    "Example: ripv dac profiles --cache cac --meta deployment.json --qc qc.yml --out dac rosie_713-2019-166-0-157.sbd rosie_713-2019-166-0-157.tbd"})
    static final class Profiles extends Subcommand {
        @Parameters(arity = "1..*", paramLabel = "FILE", description = "The glider's flight and science files, plain or compressed, in any order.")
        List<Path> files;

        @Option(names = {"-c", "--cache"}, paramLabel = "DIR", description = "The sensor-list cache folder (CRC.cac files).")
        Path cache;

        @Option(names = "--meta", required = true, paramLabel = "FILE.json",
                description = "The deployment's metadata: {\"global\": {...}, \"platform\": {...}, \"instrument_ctd\": {...}} with the template's attribute names.")
        Path meta;

        @Option(names = "--qc", paramLabel = "FILE.yml", description = "QARTOD tests in ioos_qc's YAML (variable -> qartod -> test -> parameters). Without it no QC is run.")
        Path qc;

        @Option(names = "--out", required = true, paramLabel = "DIR", description = "Where the files go (made if missing).")
        Path out;

        @Option(names = "--min-depth-span", paramLabel = "DBAR", defaultValue = "10",
                description = "A profile spans more than this many dbar (default ${DEFAULT-VALUE}).")
        double minDepthSpan;

        @Option(names = "--min-samples", paramLabel = "N", defaultValue = "14",
                description = "A profile has at least this many samples (default ${DEFAULT-VALUE}).")
        int minSamples;

        @Option(names = "--filter", paramLabel = "N", defaultValue = "7",
                description = "Samples in the running mean that smooths the pressure before its turning points are found (default ${DEFAULT-VALUE}).")
        int filter;

        @Override
        public Integer call() throws IOException {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            ProfileSplitter splitter;
            try {
                splitter = new ProfileSplitter(minDepthSpan, minSamples, filter);
            } catch (IllegalArgumentException e) {
                err.println("Error: " + e.getMessage());
                return 2;
            }
            try {
                Metadata m = Metadata.read(meta);
                QcConfig q = qc == null ? QcConfig.none() : QcConfig.read(qc);
                Files.createDirectories(this.out);
                DacRun.Result r = new DacRun(new SegmentReader(cache == null ? null : new SensorListCache(cache)), splitter,
                        new ProfileWriter(m, q), new ProfileChecker()).run(files, this.out);
                r.lines().forEach(out::println);
                out.flush();
                return r.allPassed() ? 0 : 1;
            } catch (DacException e) {
                err.println("Error: " + e.getMessage());
                return 1;
            }
        }
    }

    @Command(name = "push",
            description = {"Pushes profile files to the DAC's SFTP folder: key authentication, the host key checked against a known-hosts"
                    + " file, each file checked first, a ledger of what was sent (nothing is sent twice), retries with back-off.",
                    "Example: ripv dac push --to sftp://rosie@gliders.ioos.us/rosie_713-20190615 --key ~/.ssh/id_ecdsa --known-hosts ~/.ssh/known_hosts dac"})
    static final class Push extends Subcommand {
        @Parameters(arity = "1..*", paramLabel = "FILE.nc|DIR", description = "Profile files, or folders of them (their *.nc).")
        List<Path> files;

        @Option(names = "--to", required = true, paramLabel = "sftp://USER@HOST[:PORT]/FOLDER", description = "The deployment's folder on the DAC's SFTP server.")
        URI to;

        @Option(names = "--key", required = true, paramLabel = "FILE", description = "The private key (OpenSSH or PEM; RSA or ECDSA).")
        Path key;

        @Option(names = "--known-hosts", required = true, paramLabel = "FILE", description = "known_hosts holding the server's host key.")
        Path knownHosts;

        @Option(names = "--ledger", paramLabel = "FILE", description = "The ledger (default: dac-ledger.tsv in the first folder given, or beside the first file).")
        Path ledger;

        @Option(names = "--attempts", paramLabel = "N", defaultValue = "4", description = "Connection attempts, 1 s, 2 s, 4 s … apart (default ${DEFAULT-VALUE}).")
        int attempts;

        @Override
        public Integer call() throws IOException, InterruptedException {
            PrintWriter out = spec.commandLine().getOut();
            PrintWriter err = spec.commandLine().getErr();
            List<Path> all = new ArrayList<>();
            for (Path f : files) {
                if (Files.isDirectory(f)) {
                    try (var s = Files.list(f)) {
                        s.filter(p -> p.getFileName().toString().endsWith(".nc")).sorted().forEach(all::add);
                    }
                } else if (Files.isRegularFile(f)) {
                    all.add(f);
                } else {
                    err.println("Error: no such file or folder: " + f);
                    return 1;
                }
            }
            Path l = ledger != null ? ledger : (Files.isDirectory(files.get(0)) ? files.get(0) : files.get(0).toAbsolutePath().getParent()).resolve("dac-ledger.tsv");
            try {
                List<SftpPush.Outcome> r = new SftpPush(to, key, knownHosts, new DacLedger(l), attempts, Duration.ofSeconds(1)).push(all);
                boolean ok = true;
                for (SftpPush.Outcome o : r) {
                    out.println(o.file().getFileName() + ": " + o.status() + " (" + o.detail() + ")");
                    ok &= o.status().equals("sent") || o.status().equals("already sent");
                }
                out.println((r.isEmpty() ? "no .nc files to push" : r.stream().filter(o -> o.status().equals("sent")).count() + " sent") + "; ledger " + l);
                return ok ? 0 : 1;
            } catch (DacException e) {
                err.println("Error: " + e.getMessage());
                return 1;
            }
        }
    }

    @Command(name = "check",
            description = "Checks profile files against the DAC template's required variables, attributes and ranges (what cc-plugin-glider checks).")
    static final class Check extends Subcommand {
        @Parameters(arity = "1..*", paramLabel = "FILE.nc")
        List<Path> files;

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            boolean ok = true;
            ProfileChecker c = new ProfileChecker();
            for (Path f : files) {
                try {
                    ProfileChecker.Report r = c.check(f);
                    out.println(f.getFileName() + ": " + (r.passed() ? "passes" : "FAILS: " + String.join("; ", r.failures()))
                            + (r.warnings().isEmpty() ? "" : " (warnings: " + String.join("; ", r.warnings()) + ")"));
                    ok &= r.passed();
                } catch (IOException e) {
                    out.println(f.getFileName() + ": FAILS: not a NetCDF file we can read: " + e.getMessage());
                    ok = false;
                }
            }
            return ok ? 0 : 1;
        }
    }
}
