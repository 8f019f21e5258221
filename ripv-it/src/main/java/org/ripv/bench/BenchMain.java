package org.ripv.bench;

import java.util.Arrays;
import java.util.List;
import org.ripv.client.handlers.Tls;
import org.ripv.launch.Launchers;
import org.ripv.launch.Version;
import org.ripv.services.bench.DataVisBenchmark;
import org.ripv.services.bench.YmodemBenchmark;
import picocli.CommandLine;

/**
 * {@code ./ripv bench NAME [OPTIONS]}: the benchmarks whose figures docs/performance.md records.
 * Each measures its baseline in the same run and reports against it.
 */
public final class BenchMain {
    private BenchMain() {}

    static final String USAGE = String.join("\n",
            "Usage: ripv bench NAME [OPTIONS]   (NAME --help for its options)",
            "  broker     the client → server → service → client round trip against a bare socket and RMI call;",
            "             throughput with 1, 8 and 32 clients   [--seconds S] [--warmup S] [--clients 1,8,32]",
            "  connections  N idle logged-in TLS clients on a server with a 1 GiB heap: its threads, heap and memory,",
            "             and a logged-in user's ?services round trip meanwhile   [--clients N] [--plain] [--openers N]",
            "  database   a 100,000-row query end to end against direct JDBC   [--rows N] [--runs N] [--warmup N]",
            "  ymodem     YMODEM over a baud-paced relay as a share of the line rate, and against lrzsz",
            "             [BAUD:BYTES ...], e.g. 9600:65536 115200:1048576",
            String.join("\n", ZmodemBench.USAGE),
            "  console    the live console: 1,000 watchers of a vehicle printing 50 lines/s against one watcher,",
            "             with one more that never reads, and the same fan-out with no RIPV (the machine's floor)",
            "             [--watchers N] [--rate N] [--seconds S] [--baseline-seconds S] [--warmup S] [--raw-threads N]",
            "  web        the web console: 10,000 WebSocket watchers of a vehicle printing 50 lines/s against one,",
            "             server threads and heap, one that never reads, the fan-out floor, and the fleet page with",
            "             100 vehicles   [--watchers N] [--rate N] [--seconds S] [--baseline-seconds S] [--vehicles N] [--heap SIZE]",
            "  ingest     Slocum DBA ingest (2,136 sensors; 100,000 rows) against a direct JDBC batch insert, and",
            "             vis:track of 100,000 positions end to end",
            "             [--runs N] [--wide-runs N] [--track-runs N] [--rows N] [--only wide|long|track]",
            "  slocum     Slocum binary decoding (10 MB, plain and LZ4) in MB/s against reading the same bytes, and",
            "             binary ingest against a direct JDBC batch insert   [--mb N] [--runs N] [--ingest-rows N]",
            "  dac        IOOS Glider DAC profile files per second from decoded data (split, GSW, QARTOD, template)",
            "             against NetCDF-Java alone writing the same files   [--yos N] [--runs N]",
            "  datavis    vis: to JPEG for 10,000 and 1,000,000 points, built-in worker and Octave   [--no-octave]",
            "             [--points 10000,1000000] [--runs N]",
            "  firststart the DatabaseServer's first start (Derby created and seeded) in a fresh JVM, against",
            "             loading the scripts statement by statement   [--runs N]",
            "  calls      100 vehicles calling 100 listen:// links within a minute: accepted, streamed, delay",
            "             [--vehicles N] [--spread S] [--surface S] [--lines-per-second N]",
            "  hosts      as root, in network namespaces: the request round trip across hosts against bare TCP",
            "             between the same namespaces, cut service host -> ?services says so, and kill -9 of",
            "             the active server -> the standby answers (PostgreSQL state)   [--requests N] [--takeovers N]",
            "  store      vehicle transcript appends through the server's writer into the embedded store and into",
            "             PostgreSQL (RIPV_PG_URL) against direct JDBC batch inserts   [--entries N]",
            "  surfacing  the surface dialog parser in dialog lines per second against reading and splitting the same lines",
            "             [--dialogs N] [--runs N]",
            "  plans      checking Slocum behaviour files (.ma) in files per second against reading the same files",
            "             [--files N] [--runs N]",
            "  webload    the web console's fleet page with 100 vehicles in headless Chromium: time to every vehicle",
            "             shown against the same page static in the same browser   [--vehicles N] [--runs N]",
            "  workflow   the simulator calls in with a queued workflow (dir, ymodem:get of 5 files, 500 KB, ymodem:put",
            "             of 100 KB) at 115200 baud: call → WORKFLOW_DONE against the transfers alone, same run",
            "             [--baud N] [--runs N] [--files N] [--get-bytes N] [--put-bytes N] [--report-only]",
            "Every benchmark takes --short: counts and times shrunk to seconds, to check that it still runs (CI does);",
            "its figures mean little. See docs/performance.md for what each measures and the figures.");

    /** What {@code ripv bench --help} prints: the one list of benchmarks the docs' lists must equal. */
    public static String usage() {
        return USAGE;
    }

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /**
     * Runs one benchmark and returns its exit status; nothing here or in the benchmarks exits, so
     * {@link ShortRuns} runs every {@code --short} run in one JVM (issue 38).
     */
    public static int run(String[] args) throws Exception {
        if (args.length == 0 || args[0].equals("--help") || args[0].equals("-h")) {
            System.out.println(USAGE);
            return args.length == 0 ? 2 : 0;
        }
        if (args[0].equals("--version") || args[0].equals("-V")) {
            System.out.println(Version.line());
            return 0;
        }
        String[] rest = ShortMode.apply(args[0], Arrays.copyOfRange(args, 1, args.length));
        if (!List.of("broker", "calls", "workflow").contains(args[0]) && (Arrays.asList(rest).contains("--help") || Arrays.asList(rest).contains("-h"))) {
            System.out.println(USAGE); // the benchmarks without a picocli command of their own
            return 0;
        }
        // The one place every --short run says, first and last, that its figures are not measurements.
        boolean isShort = ShortMode.announce(args, System.out);
        try {
            return dispatch(args[0], rest);
        } finally {
            if (isShort) {
                System.out.println(ShortMode.NOT_MEASUREMENTS);
            }
        }
    }

    private static int dispatch(String name, String[] rest) throws Exception {
        // Each run's server makes a new certificate: keep them out of the user's ~/.ripv/known_hosts.
        java.nio.file.Path known = java.nio.file.Files.createTempFile("ripv-bench-known-hosts", "");
        known.toFile().deleteOnExit();
        System.setProperty(Tls.KNOWN_HOSTS_PROPERTY, known.toString());
        if (ShortMode.names().contains(name)) {
            System.out.println(CpuClock.machineLine()); // how loaded the machine was, beside every benchmark's figures
        }
        return switch (name) {
            case "broker" -> Launchers.commandLine(new BrokerBench(), "ripv bench broker").execute(rest);
            case "database" -> DatabaseBench.run(rest);
            case "connections" -> Launchers.commandLine(new ConnectionCostBench()).execute(rest);
            case "console" -> Launchers.commandLine(new ConsoleBench()).execute(rest);
            case "web" -> Launchers.commandLine(new WebBench()).execute(rest);
            case "ymodem" -> YmodemBenchmark.run(rest);
            case "zmodem" -> ZmodemBench.run(rest);
            case "datavis" -> DataVisBenchmark.run(rest);
            case "firststart" -> FirstStartBench.run(rest);
            case "calls" -> Launchers.commandLine(new CallsBench(), "ripv bench calls").execute(rest);
            case "ingest" -> IngestBench.run(rest);
            case "slocum" -> SlocumBench.run(rest);
            case "dac" -> DacBench.run(rest);
            case "hosts" -> HostsBench.run(rest);
            case "store" -> StoreBench.run(rest);
            case "surfacing" -> SurfacingBench.run(rest);
            case "plans" -> PlansBench.run(rest);
            case "webload" -> WebLoadBench.run(rest);
            case "workflow" -> Launchers.commandLine(new WorkflowBench(), "ripv bench workflow").execute(rest);
            default -> {
                System.err.println("Error: unknown benchmark '" + name + "'\n" + USAGE);
                yield 2;
            }
        };
    }
}
