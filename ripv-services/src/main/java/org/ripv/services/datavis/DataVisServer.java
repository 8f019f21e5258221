package org.ripv.services.datavis;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.exceptions.ServiceException;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.Attachment;
import org.ripv.messages.ChartData;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.Progress;
import org.ripv.naming.Handles;
import org.ripv.service.Availability;
import org.ripv.service.CommandHandler;
import org.ripv.service.RIPVService;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The DataVisServer (thesis 4.1.4.3, SID 999999): turns an operator's data file into a JPEG plot.
 *
 * <p>{@code vis:NAME [options]} — the server attaches NAME from its upload directory; this
 * service checks and normalizes it, and hands it to a plot worker through the thesis's file
 * exchange in its work directory ({@link Exchange}): {@code data.dat}, {@code info.dat}, then the
 * worker's {@code <output>.jpg} and {@code ok.dat}. The reply carries the JPEG as an
 * {@link ImageResult}, which the server stores in its download directory and the client shows.
 *
 * <p>One MailBox per work directory (handle {@link Handles#platformDefault()}), so one plot at a
 * time there. The worker is the built-in JFreeChart one, {@code octave-cli} on {@code ripvOut.m}
 * (started and restarted here, {@link PlotWorkers}), or one started by hand ({@link WorkerMode}).
 * <pre>{@code
 * DataVisServer vis = new DataVisServer(host, DataVisServer.Config.of(Path.of("/var/ripv/vis")));
 * ServiceConnector.connect(vis, options);
 * }</pre>
 */
public final class DataVisServer extends RIPVService {
    private static final Logger log = LoggerFactory.getLogger(DataVisServer.class);

    /**
     * How the service runs.
     *
     * @param workDir the exchange directory (the thesis's "Matlab working directory")
     * @param worker  which worker plots
     * @param timeout how long a plot may take before the request fails
     * @param octave  the Octave program for {@link WorkerMode#OCTAVE}
     * @param script  the ripvOut.m to run, or null for the copy in the jar
     */
    public record Config(Path workDir, WorkerMode worker, Duration timeout, String octave, Path script) {
        public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(60);

        public Config {
            Objects.requireNonNull(workDir, "workDir");
            worker = worker == null ? WorkerMode.BUILTIN : worker;
            timeout = timeout == null ? DEFAULT_TIMEOUT : timeout;
            if (timeout.isNegative() || timeout.isZero()) {
                throw new IllegalArgumentException("the timeout must be positive, not " + timeout);
            }
            octave = octave == null || octave.isBlank() ? "octave-cli" : octave;
        }

        /** The built-in worker in {@code workDir}, 60 s timeout. */
        public static Config of(Path workDir) {
            return new Config(workDir, WorkerMode.BUILTIN, DEFAULT_TIMEOUT, null, null);
        }

        public Config withWorker(WorkerMode mode) {
            return new Config(workDir, mode, timeout, octave, script);
        }

        public Config withTimeout(Duration t) {
            return new Config(workDir, worker, t, octave, script);
        }
    }

    private final Config config;
    private final Path dir;
    private final AtomicLong sequence = new AtomicLong();
    private final PlotWorkers workers;
    private final PlotCancel plotCancel = new PlotCancel();

    public DataVisServer(String host, Config config) {
        super("DataVisServer", Ids.SID_DATAVIS, host);
        this.config = config;
        this.dir = config.workDir().toAbsolutePath().normalize();
        this.workers = new PlotWorkers(config, dir);
    }

    public DataVisServer(Config config) {
        this(Handles.localHost(), config);
    }

    public Config config() {
        return config;
    }

    /** The work directory. */
    public Path workDir() {
        return dir;
    }

    @Override
    protected String description() {
        return "Plots data files to JPEG: vis:NAME [title=\"...\"] [legend=a|b] [out=NAME] (worker: " + config.worker() + ")";
    }

    @Override
    protected String panel() {
        return "DAV";
    }

    @Override
    protected List<String> attachPrefixes() {
        return List.of(VisCommand.PREFIX);
    }

    @Override
    protected void open() throws Exception {
        PrivateFiles.createDirectories(dir);
        PrivateFiles.restrict(dir); // 0700: operators' data and plots are not for every local user
        int stale = Exchange.clean(dir);
        if (stale > 0) {
            log.info("removed {} exchange file(s) left in {} by an earlier run", stale, dir);
        }
        workers.start();
        openMailBox(Handles.platformDefault(), new Handler());
    }

    @Override
    protected void close() {
        workers.close();
    }

    private final class Handler implements CommandHandler {
        @Override
        public Availability availability() {
            return workers.availability();
        }

        /** Stops the running plot: its wait ends and the worker is stopped (it is started again for the next one). */
        @Override
        public boolean cancel(Request running) {
            if (!plotCancel.ask()) {
                return false;
            }
            workers.stop();
            return true;
        }

        @Override
        public Reply execute(Request request) throws Exception {
            plotCancel.start();
            try {
                Reply reply = run(request);
                if (plotCancel.asked()) {
                    // the operator was told the cancel was taken; the reply says so even if the work had ended
                    throw new ServiceException(ErrorCode.CANCELLED, "'" + request.command().strip() + "' cancelled");
                }
                return reply;
            } finally {
                plotCancel.end();
            }
        }

        private Reply run(Request request) throws Exception {
            String line = request.command().strip();
            if (line.equalsIgnoreCase("help")) {
                return Reply.ok("vis:NAME [out=NAME] [title=\"...\"] [xlabel=\"...\"] [ylabel=\"...\"] [legend=a|b|c] "
                        + "[size=800x600] plots NAME from the upload directory; worker: " + config.worker());
            }
            if (!line.regionMatches(true, 0, VisCommand.PREFIX, 0, VisCommand.PREFIX.length())) {
                String word = line.split("\\s+", 2)[0];
                return Reply.error(ErrorCode.UNKNOWN_COMMAND, "the DataVisServer knows vis:NAME [options] and help, not '"
                        + word + "'");
            }
            if (DbaPlot.matches(line)) {
                return plotDba(request, line);
            }
            VisCommand vis;
            try {
                vis = VisCommand.parse(line);
            } catch (IllegalArgumentException e) {
                return Reply.error(ErrorCode.BAD_REQUEST, e.getMessage());
            }
            Optional<Attachment> file = request.attachment();
            if (file.isEmpty()) {
                return Reply.error(ErrorCode.BAD_REQUEST, "vis:" + vis.file() + " found no file '" + vis.file()
                        + "' attached: upload it to the server first (CLI: put " + vis.file() + "), then check ?ulfiles");
            }
            return plot(request, vis, file.get());
        }
    }

    /** {@code vis:file NAME x=... y=...}: a downloaded DBA file's columns, drawn like any data file. */
    private Reply plotDba(Request request, String line) throws Exception {
        DbaPlot p;
        try {
            p = DbaPlot.parse(line);
        } catch (IllegalArgumentException e) {
            return Reply.error(ErrorCode.BAD_REQUEST, e.getMessage());
        }
        Optional<Attachment> attached = request.attachment();
        if (attached.isEmpty() || attached.get().files(1).isEmpty()) {
            return Reply.error(ErrorCode.BAD_REQUEST, "vis:file found no file '" + p.file() + "' attached: it must be in the"
                    + " server's download directory (?dlfiles)");
        }
        byte[] data;
        try {
            data = p.data(attached.get().files(1).get(0));
        } catch (DataFormatException e) {
            return Reply.error(ErrorCode.BAD_REQUEST, p.file() + ": " + e.getMessage());
        }
        return plot(request, VisCommand.parse("vis:" + p.output() + ".dat out=" + p.output()),
                new Attachment(p.output() + ".dat", data));
    }

    /** {@code vis:file NAME ...}: the server attaches NAME from its download directory. */
    @Override
    protected List<String> downloadPrefixes() {
        return List.of(DbaPlot.PREFIX);
    }

    private Reply plot(Request request, VisCommand vis, Attachment file) throws Exception {
        long t0 = System.nanoTime();
        if (plotCancel.asked()) {
            throw cancelled(request, file);
        }
        workers.ensureBuiltin();
        String exchangeName = vis.output() + "-" + sequence.incrementAndGet(); // a late worker's JPEG never passes for ours
        String jpegName = vis.output() + ".jpg";
        Exchange.clean(dir);
        try (WatchService watch = FileSystems.getDefault().newWatchService()) {
            dir.register(watch, StandardWatchEventKinds.ENTRY_CREATE, StandardWatchEventKinds.ENTRY_MODIFY);
            plotCancel.begin(watch);
            DataFile.Summary summary = writeData(vis, file);
            Exchange.writeAtomically(dir, Exchange.INFO, (exchangeName + "\n").getBytes(StandardCharsets.UTF_8));
            request.progress("plotting " + summary.rows() + " rows of " + file.name() + " with the " + config.worker()
                    + " worker", new Progress("rows checked and handed to the " + config.worker() + " worker",
                            summary.rows(), summary.rows(), 0));
            // The chart's numbers for an interactive plot in the client, while the worker draws.
            ChartData chart = ChartDataBuilder.forReply(config.worker(), file.data(), summary);
            String status;
            try {
                status = awaitWorker(watch, vis, exchangeName);
            } catch (ClosedWatchServiceException e) {
                if (!plotCancel.asked()) {
                    throw e;
                }
                status = null;
            }
            // A cancel taken as the worker finished still cancels: the operator was told it was
            // taken, and the worker has been stopped all the same.
            if (plotCancel.asked()) {
                throw cancelled(request, file);
            }
            if (!status.equals("1") && !status.isEmpty()) {
                String why = status.startsWith("0") ? status.substring(1).strip() : status;
                throw new ServiceException(ErrorCode.WORKER_ERROR, "the " + config.worker() + " worker could not plot "
                        + file.name() + ": " + (why.isEmpty() ? "(no reason given)" : why));
            }
            Path jpeg = dir.resolve(Exchange.jpegName(exchangeName));
            if (!Files.isRegularFile(jpeg)) {
                throw new ServiceException(ErrorCode.WORKER_ERROR, "the " + config.worker() + " worker reported success but wrote no "
                        + jpeg.getFileName() + " in " + dir);
            }
            byte[] bytes = Files.readAllBytes(jpeg);
            if (bytes.length < 4 || (bytes[0] & 0xff) != 0xFF || (bytes[1] & 0xff) != 0xD8) {
                throw new ServiceException(ErrorCode.WORKER_ERROR, "the " + config.worker() + " worker wrote "
                        + jpeg.getFileName() + " but it is not a JPEG (" + bytes.length + " bytes)");
            }
            long ms = (System.nanoTime() - t0) / 1_000_000;
            log.info("vis:{} -> {} ({} rows, {} bytes) in {} ms for {}", file.name(), jpegName, summary.rows(), bytes.length,
                    ms, request.user());
            return Reply.ok("plotted " + summary.rows() + " rows x " + Math.max(1, summary.columns() - 1) + " series of "
                    + file.name() + " to " + jpegName + " (" + bytes.length + " bytes) in " + ms + " ms with the "
                    + config.worker() + " worker", new ImageResult(jpegName, bytes, chart));
        } finally {
            Exchange.clean(dir); // whatever happened, the next request starts from an empty exchange
        }
    }

    private ServiceException cancelled(Request request, Attachment file) {
        log.info("vis:{} for {} was cancelled; the {} worker was stopped", file.name(), request.user(), config.worker());
        return new ServiceException(ErrorCode.CANCELLED, "plot of " + file.name() + " cancelled; the "
                + config.worker() + " worker was stopped and starts again for the next plot");
    }

    /** Checks the operator's file and writes the canonical data.dat (complete before it appears). */
    private DataFile.Summary writeData(VisCommand vis, Attachment file) throws IOException, ServiceException {
        Path tmp = dir.resolve(Exchange.DATA + Exchange.TMP_SUFFIX);
        DataFile.Summary summary;
        try (BufferedWriter out = new BufferedWriter(new OutputStreamWriter(Files.newOutputStream(tmp), StandardCharsets.UTF_8),
                1 << 16)) {
            summary = DataFile.normalize(file.data(), vis.labels(), out);
        } catch (DataFormatException e) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, file.name() + ": " + e.getMessage());
        }
        Exchange.move(tmp, dir.resolve(Exchange.DATA));
        return summary;
    }

    /**
     * Waits for this request's ok.dat and returns its first line. An ok.dat that appears while
     * our data.dat or info.dat is still there, and without our JPEG, was written for an earlier,
     * abandoned request: the protocol has the worker remove both inputs before it writes ok.dat.
     * (With our JPEG present it is ours even so: appendix D's original script wrote ok.dat first.)
     */
    private String awaitWorker(WatchService watch, VisCommand vis, String exchangeName)
            throws IOException, InterruptedException, ServiceException {
        Path ok = dir.resolve(Exchange.OK);
        Path data = dir.resolve(Exchange.DATA);
        Path info = dir.resolve(Exchange.INFO);
        Path jpeg = dir.resolve(Exchange.jpegName(exchangeName));
        long deadline = System.nanoTime() + config.timeout().toNanos();
        while (true) {
            if (Files.exists(ok)) {
                if (Files.exists(jpeg) || (!Files.exists(data) && !Files.exists(info))) {
                    return Exchange.firstLine(ok).orElse("");
                }
                log.info("removing a stale {} from an earlier request", Exchange.OK);
                Files.deleteIfExists(ok);
            }
            long left = deadline - System.nanoTime();
            WatchKey key = left > 0 ? watch.poll(left, TimeUnit.NANOSECONDS) : null; // sleeps until the directory changes
            if (key == null) {
                throw new ServiceException(ErrorCode.TIMEOUT, workers.noAnswer(vis, config.timeout()));
            }
            key.pollEvents();
            key.reset();
        }
    }


}
