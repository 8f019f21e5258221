package org.ripv.services.datavis;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The built-in plot worker: the Java twin of {@code ripvOut.m}. It watches a work directory,
 * and for each {@code data.dat} + {@code info.dat} pair draws the plot with JFreeChart, writes
 * {@code <output>.jpg}, removes the pair and writes {@code ok.dat} — the {@link Exchange} protocol
 * and nothing else, so it runs equally as a thread of the DataVisServer or as its own process:
 * <pre>{@code java -cp ripv-services.jar org.ripv.services.datavis.PlotWorker WORKDIR}</pre>
 * Waiting is on the file system's change notifications, not a polling loop.
 */
public final class PlotWorker implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(PlotWorker.class);

    private final Path dir;
    private final WatchService watch;
    private final Thread thread;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private final AtomicLong plots = new AtomicLong();
    private volatile boolean closing;

    private PlotWorker(Path dir) throws IOException {
        this.dir = dir.toAbsolutePath();
        PrivateFiles.createDirectories(this.dir);
        PrivateFiles.restrict(this.dir);
        this.watch = FileSystems.getDefault().newWatchService();
        this.dir.register(watch, StandardWatchEventKinds.ENTRY_CREATE, StandardWatchEventKinds.ENTRY_MODIFY);
        this.thread = new Thread(this::run, "ripv-datavis-worker-" + this.dir.getFileName());
        this.thread.setDaemon(true);
    }

    /** Starts a worker thread on {@code dir}. */
    public static PlotWorker start(Path dir) throws IOException {
        PlotWorker w = new PlotWorker(dir);
        w.thread.start();
        log.info("built-in plot worker watching {}", w.dir);
        return w;
    }

    /** Whether the worker thread is running. */
    public boolean isAlive() {
        return thread.isAlive();
    }

    /** Plots made so far. */
    public long plots() {
        return plots.get();
    }

    /** Waits until the worker has stopped (after {@link #close} or a {@code stop.dat}). */
    public void await() throws InterruptedException {
        stopped.await();
    }

    private void run() {
        Path data = dir.resolve(Exchange.DATA);
        Path info = dir.resolve(Exchange.INFO);
        Path stop = dir.resolve(Exchange.STOP);
        try {
            PlotRenderer.warmUp(); // class loading and fonts now, not in the first operator's request
            while (!closing) {
                if (Files.exists(data) && Files.exists(info)) {
                    plotOnce(data, info);
                    continue;
                }
                if (Files.exists(stop)) { // after any pending plot, so "plot this, then stop" works
                    Files.deleteIfExists(stop);
                    log.info("{} found: the plot worker in {} stops", Exchange.STOP, dir);
                    break;
                }
                WatchKey key = watch.take(); // sleeps until something in the directory changes
                key.pollEvents();
                if (!key.reset()) {
                    log.error("the work directory {} is gone; the plot worker stops", dir);
                    break;
                }
            }
        } catch (InterruptedException | ClosedWatchServiceException e) {
            // closing
        } catch (IOException | RuntimeException e) {
            log.error("the plot worker in {} failed", dir, e);
        } finally {
            try {
                watch.close();
            } catch (IOException ignored) {
                // nothing left to release
            }
            stopped.countDown();
        }
    }

    private void plotOnce(Path data, Path info) throws IOException {
        String status;
        String output = Exchange.firstLine(info).orElse("");
        try {
            if (!Exchange.validOutputName(output.replaceFirst("(?i)\\.jpg$", ""))) {
                throw new IOException("info.dat names no usable output: '" + output + "'");
            }
            long t0 = System.nanoTime();
            PlotRenderer.Rendered r = PlotRenderer.render(data);
            Exchange.writeAtomically(dir, Exchange.jpegName(output), r.jpeg());
            plots.incrementAndGet();
            log.info("plotted {} rows, {} series ({} points drawn) to {} in {} ms", r.rows(), r.series(), r.points(),
                    Exchange.jpegName(output), (System.nanoTime() - t0) / 1_000_000);
            status = "1";
        } catch (DataFormatException | IOException | RuntimeException e) {
            log.warn("could not plot {}: {}", output, e.getMessage());
            String m = e.getMessage() == null ? e.toString() : e.getMessage();
            status = "0 " + m.replaceAll("\\p{Cntrl}", " ");
        } catch (OutOfMemoryError e) {
            status = "0 out of memory while plotting";
        }
        if (!output.equals(Exchange.firstLine(info).orElse(""))) {
            // The service gave up on this round (timeout) and may have written the next one: touch nothing of it.
            log.warn("the request for {} was abandoned while it was being plotted; result dropped", output);
            Files.deleteIfExists(dir.resolve(Exchange.jpegName(output)));
            return;
        }
        // Input files go before ok.dat appears, so the service may write the next pair at once
        // (the thesis's script deleted them after ok.dat, racing the next request).
        Files.deleteIfExists(data);
        Files.deleteIfExists(info);
        Exchange.writeAtomically(dir, Exchange.OK, (status + "\n").getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Tells the worker to stop and does not wait (a cancelled plot): a plot it is drawing is
     * dropped, since the request that wanted it has cleaned the exchange.
     */
    public void stop() {
        closing = true;
        thread.interrupt();
    }

    /** Stops the worker thread and waits for it. */
    @Override
    public void close() {
        closing = true;
        thread.interrupt();
        try {
            watch.close();
            stopped.await();
        } catch (IOException e) {
            log.debug("closing the watch service", e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Runs the built-in worker as its own process on a work directory until it is killed or a
     * {@code stop.dat} appears there. Usage: {@code PlotWorker WORKDIR}.
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 1) {
            System.err.println("usage: PlotWorker WORKDIR   (plots data.dat + info.dat pairs until stop.dat appears)");
            System.exit(2);
        }
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        PlotWorker w = start(Path.of(args[0]));
        w.await();
    }
}
