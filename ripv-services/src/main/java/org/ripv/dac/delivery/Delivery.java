package org.ripv.dac.delivery;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;
import org.ripv.dac.DacException;
import org.ripv.dac.DacLedger;
import org.ripv.dac.DacRun;
import org.ripv.dac.ProfileChecker;
import org.ripv.dac.ProfilePush;
import org.ripv.dac.ProfileWriter;
import org.ripv.dac.SegmentReader;
import org.ripv.dac.SftpPush;
import org.ripv.retry.Backoff;
import org.ripv.services.ingest.SensorListCache;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One running deployment. Each Slocum file the ingest stored is kept in {@code FOLDER/incoming/};
 * when a segment has its science file ({@code .tbd/.tcd}, {@code .ebd/.ecd}) and its flight file
 * ({@code .sbd/.scd}, {@code .dbd/.dcd}) of one mode, its profiles are made in a staging folder
 * and each new one moved to {@code profiles/} (or {@code failed/} when it fails the check, kept and
 * reported, never sent). A profile is made once: the same segment arriving again adds nothing,
 * and a delayed-mode profile moves the real-time one of the same dive to {@code replaced/}. Then
 * every profile not yet sent is pushed ({@link ProfilePush}, the ledger {@code dac-ledger.tsv}); a
 * push that fails is tried again after a back-off ({@link Backoff}), and the ledger keeps a file
 * from being sent twice. Everything runs on the deployment's own thread: an ingest never waits
 * for it, and a refusal (no science, NaN-only CTD, a clock that steps back, a file too large)
 * is a line of its state, with nothing of the segment written.
 */
public final class Delivery implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Delivery.class);
    private static final List<String> SCIENCE_RT = List.of("tbd", "tcd");
    private static final List<String> FLIGHT_RT = List.of("sbd", "scd");
    private static final List<String> SCIENCE_DELAYED = List.of("ebd", "ecd");
    private static final List<String> FLIGHT_DELAYED = List.of("dbd", "dcd");

    private final Deployment deployment;
    private final DeliveryState state;
    private final ProfilePush push;
    private final ProfileWriter writer;
    private final ProfileChecker checker = new ProfileChecker();
    private final Path incoming;
    private final Path profiles;
    private final Path failed;
    private final Path replaced;
    private final ScheduledExecutorService worker;
    /** Owned by the worker thread. */
    private final Backoff backoff;
    private ScheduledFuture<?> retry;

    private Delivery(Deployment d) throws DacException, IOException {
        this.deployment = d;
        Path folder = d.folder();
        this.incoming = Files.createDirectories(folder.resolve("incoming"));
        this.profiles = Files.createDirectories(folder.resolve("profiles"));
        this.failed = Files.createDirectories(folder.resolve("failed"));
        this.replaced = Files.createDirectories(folder.resolve("replaced"));
        this.state = new DeliveryState(folder.resolve("delivery-state.json"));
        this.push = d.push(new DacLedger(folder.resolve("dac-ledger.tsv")));
        this.writer = new ProfileWriter(d.metadata(), d.qc());
        this.backoff = new Backoff(d.firstRetry(), d.maxRetry());
        this.worker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "ripv-dac-" + d.glider());
            t.setDaemon(true);
            return t;
        });
        worker.execute(this::pushWaiting); // what a restart left unsent
    }

    /** Starts a deployment: its folders, its state as it was left, its push. */
    public static Delivery start(Deployment d) throws DacException, IOException {
        return new Delivery(d);
    }

    public Deployment deployment() {
        return deployment;
    }

    /** True for a Slocum file of this deployment's glider: its name before the first '-' is the glider's. */
    public boolean takes(String name) {
        String base = Path.of(name).getFileName().toString();
        int dash = base.indexOf('-');
        return dash > 0 && base.substring(0, dash).equalsIgnoreCase(deployment.glider()) && extension(base) != null;
    }

    /** A file the ingest stored; made into profiles and pushed on the deployment's thread. */
    public void arrived(String name, byte[] data, SensorListCache cache) {
        try {
            worker.execute(() -> receive(Path.of(name).getFileName().toString(), data, cache));
        } catch (RejectedExecutionException e) {
            // the service is stopping: the file is stored; its profiles are made when it arrives again
            log.warn("DAC delivery of {} is stopped: {} not taken", deployment.glider(), name);
        }
    }

    /** Waits until every arrival so far is handled (tests, and a clean stop). */
    public void settle(long timeoutMillis) throws InterruptedException {
        try {
            worker.submit(() -> { }).get(timeoutMillis, TimeUnit.MILLISECONDS);
        } catch (ExecutionException | TimeoutException e) {
            throw new IllegalStateException("the delivery of " + deployment.glider() + " did not settle: " + e, e);
        }
    }

    public String text() {
        return state.text(deployment, Instant.now());
    }

    public Map<String, Object> json() {
        return state.json(deployment, Instant.now());
    }

    private void receive(String name, byte[] data, SensorListCache cache) {
        String ext = extension(name);
        String stem = name.substring(0, name.length() - ext.length() - 1);
        boolean delayed = SCIENCE_DELAYED.contains(ext) || FLIGHT_DELAYED.contains(ext);
        String segment = stem + (delayed ? " (delayed)" : "");
        try {
            keep(name, data);
            Optional<Path> science = find(stem, delayed ? SCIENCE_DELAYED : SCIENCE_RT);
            Optional<Path> flight = find(stem, delayed ? FLIGHT_DELAYED : FLIGHT_RT);
            if (science.isEmpty() || flight.isEmpty()) {
                state.note(segment, "waiting", science.isEmpty()
                        ? "its science file (" + String.join("/", delayed ? SCIENCE_DELAYED : SCIENCE_RT) + ") has not come"
                        : "its flight file (" + String.join("/", delayed ? FLIGHT_DELAYED : FLIGHT_RT) + ") has not come");
                return;
            }
            make(segment, List.of(flight.get(), science.get()), cache);
        } catch (IOException | RuntimeException e) {
            log.warn("DAC delivery of {}: {} failed", deployment.glider(), name, e);
            note(segment, "refused", "could not be handled: " + e);
        }
        pushWaiting();
    }

    private void make(String segment, List<Path> files, SensorListCache cache) throws IOException {
        Path stage = Files.createTempDirectory(deployment.folder(), ".staging-");
        try {
            DacRun.Result r = new DacRun(new SegmentReader(cache), deployment.splitter(), writer, checker).run(files, stage);
            int added = 0;
            for (DacRun.Made m : r.made()) {
                String name = ProfileWriter.fileName(m.profile());
                if (state.has(name) || state.has(name.replace("_rt.nc", "_delayed.nc"))) {
                    continue; // made before (a profile is made once), or its delayed-mode file is there already
                }
                added++;
                double[] p = m.profile().pressure();
                double[] t = m.profile().time();
                String qc = m.qc();
                if (m.report().passed()) {
                    Files.move(m.file(), profiles.resolve(name), StandardCopyOption.REPLACE_EXISTING);
                    String detail = m.report().warnings().isEmpty() ? "" : "warnings: " + String.join("; ", m.report().warnings());
                    state.put(new DeliveryState.Entry(name, segment, m.profile().delayed() ? "delayed" : "real-time",
                            m.profile().direction() > 0 ? "dive" : "climb", p.length, min(p), max(p), qc, "written", detail,
                            t[t.length - 1], Instant.now().toString(), Instant.now().toString()));
                    if (m.profile().delayed()) {
                        replaceRealTime(name);
                    }
                } else {
                    Files.move(m.file(), failed.resolve(name), StandardCopyOption.REPLACE_EXISTING);
                    state.put(new DeliveryState.Entry(name, segment, m.profile().delayed() ? "delayed" : "real-time",
                            m.profile().direction() > 0 ? "dive" : "climb", p.length, min(p), max(p), qc, "failed the check",
                            "kept in failed/, not sent: " + String.join("; ", m.report().failures()), t[t.length - 1],
                            Instant.now().toString(), Instant.now().toString()));
                }
            }
            if (r.made().isEmpty()) {
                state.note(segment, "no profile", String.join("; ", r.lines()));
            } else {
                state.clearNote(segment);
            }
            log.info("DAC delivery of {}: {} gave {} new profile(s) of {}", deployment.glider(), segment, added, r.made().size());
        } catch (DacException e) {
            state.note(segment, "refused", "no profile written: " + e.getMessage());
            log.info("DAC delivery of {}: {} refused: {}", deployment.glider(), segment, e.getMessage());
        } finally {
            deleteTree(stage);
        }
    }

    /** A delayed-mode profile takes the place of the real-time one of the same dive (the same first time). */
    private void replaceRealTime(String delayedName) throws IOException {
        String rtName = delayedName.replace("_delayed.nc", "_rt.nc");
        DeliveryState.Entry rt = state.get(rtName);
        if (rt == null || rt.status().equals("replaced")) {
            return;
        }
        Path f = profiles.resolve(rtName);
        if (Files.exists(f)) {
            Files.move(f, replaced.resolve(rtName), StandardCopyOption.REPLACE_EXISTING);
        }
        state.put(rt.with("replaced", "by " + delayedName + (rt.status().equals("sent") ? " (the real-time file was sent before)" : "")));
    }

    /** Pushes every profile not yet sent; on a failure, tries again after the back-off. */
    private void pushWaiting() {
        List<Path> files = new ArrayList<>();
        for (String n : state.toSend()) {
            Path f = profiles.resolve(n);
            if (Files.isRegularFile(f)) {
                files.add(f);
            }
        }
        if (files.isEmpty()) {
            return;
        }
        boolean anyFailed = false;
        try {
            for (SftpPush.Outcome o : push.push(files)) {
                String name = o.file().getFileName().toString();
                DeliveryState.Entry e = state.get(name);
                switch (o.status()) {
                    case "sent", "already sent" -> state.put(e.with("sent", o.detail() + " at " + Instant.now()));
                    case "not sent" -> {
                        Files.move(o.file(), failed.resolve(name), StandardCopyOption.REPLACE_EXISTING);
                        state.put(e.with("failed the check", o.detail()));
                    }
                    default -> {
                        anyFailed = true;
                        state.put(e.with("push failed", o.detail()));
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            anyFailed = true;
            log.warn("DAC delivery of {}: the push failed: {}", deployment.glider(), e.toString());
            for (Path f : files) {
                DeliveryState.Entry en = state.get(f.getFileName().toString());
                try {
                    state.put(en.with("push failed", e.toString()));
                } catch (IOException ignored) {
                    // the state file is written again on the next change
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        if (anyFailed) {
            if (retry == null || retry.isDone()) {
                long wait = backoff.nextMillis();
                log.info("DAC delivery of {}: trying the push again in {} ms", deployment.glider(), wait);
                retry = worker.schedule(this::pushWaiting, wait, TimeUnit.MILLISECONDS);
            }
        } else {
            backoff.reset();
        }
    }

    private void note(String segment, String status, String detail) {
        try {
            state.note(segment, status, detail);
        } catch (IOException e) {
            log.warn("DAC delivery of {}: cannot save its state: {}", deployment.glider(), e.toString());
        }
    }

    private void keep(String name, byte[] data) throws IOException {
        Path tmp = incoming.resolve("." + name + ".part");
        Files.write(tmp, data);
        Files.move(tmp, incoming.resolve(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    private Optional<Path> find(String stem, List<String> extensions) {
        for (String e : extensions) {
            for (String x : List.of(e, e.toUpperCase(Locale.ROOT))) {
                Path p = incoming.resolve(stem + "." + x);
                if (Files.isRegularFile(p)) {
                    return Optional.of(p);
                }
            }
        }
        return Optional.empty();
    }

    /** The file's Slocum extension (lower case) when it is one a profile is made from, else null. */
    static String extension(String name) {
        int dot = name.lastIndexOf('.');
        if (dot <= 0) {
            return null;
        }
        String e = name.substring(dot + 1).toLowerCase(Locale.ROOT);
        return SCIENCE_RT.contains(e) || FLIGHT_RT.contains(e) || SCIENCE_DELAYED.contains(e) || FLIGHT_DELAYED.contains(e)
                ? e : null;
    }

    private static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double x : v) {
            m = Math.min(m, x);
        }
        return m;
    }

    private static double max(double[] v) {
        double m = Double.NEGATIVE_INFINITY;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }

    private static void deleteTree(Path dir) {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            log.warn("cannot remove the staging folder {}: {}", dir, e.toString());
        }
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }
}
