package org.ripv.services.simulator;

import java.io.EOFException;
import java.io.IOException;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.services.serial.Link;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulator's side of an Iridium-like call over a fast link: both directions paced to the
 * baud rate and delayed by the latency ({@link PacedPipe}), and the call dropped after a time or
 * a number of bytes, as a satellite call drops. The shore sees what it would over the real
 * thing: an ETA that matches 2,400 baud, a Ctrl-C that takes a second to arrive, a cut transfer.
 *
 * <p>Threads: {@code glider-simulator-line-in} reads the real link into the inbound pipe,
 * {@code glider-simulator-line-out} writes the outbound pipe's pieces when they are due; both end
 * with the call. Drops after a time are scheduled on one shared daemon thread.
 */
final class IridiumLine implements Link {
    private static final Logger log = LoggerFactory.getLogger(IridiumLine.class);
    private static final ScheduledExecutorService DROPS = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "glider-simulator-line-drops");
        t.setDaemon(true);
        return t;
    });

    /**
     * What the line is like.
     *
     * @param baud           bits a second each way, 0 for the link's own speed
     * @param latency        how long each byte takes to cross, each way
     * @param dropAfterTime  the call drops this long after it began, or null
     * @param dropAfterBytes the call drops once this many bytes have crossed (both ways), or 0
     */
    record Settings(int baud, Duration latency, Duration dropAfterTime, long dropAfterBytes) {
        static final Settings NONE = new Settings(0, Duration.ZERO, null, 0);

        boolean any() {
            return baud > 0 || !latency.isZero() || dropAfterTime != null || dropAfterBytes > 0;
        }

        /** {@code 1s}, {@code 500ms}, {@code 2m}: a latency or a time. */
        static Duration duration(String option, String text) {
            Matcher m = Pattern.compile("(\\d{1,7})(ms|s|m)").matcher(text.strip());
            if (!m.matches()) {
                throw new IllegalArgumentException(option + " '" + text + "' is not a time: write e.g. 500ms, 1s or 2m");
            }
            long n = Long.parseLong(m.group(1));
            return switch (m.group(2)) {
                case "ms" -> Duration.ofMillis(n);
                case "s" -> Duration.ofSeconds(n);
                default -> Duration.ofMinutes(n);
            };
        }

        /** {@code --drop-after}: {@code 60s} (a time) or {@code 40000b} (bytes, both ways together). */
        static Settings withDrop(int baud, Duration latency, String dropAfter) {
            if (dropAfter == null) {
                return new Settings(baud, latency, null, 0);
            }
            String d = dropAfter.strip().toLowerCase(Locale.ROOT);
            if (d.matches("\\d{1,12}b")) {
                long bytes = Long.parseLong(d.substring(0, d.length() - 1));
                if (bytes < 1) {
                    throw new IllegalArgumentException("--drop-after '" + dropAfter + "' must be at least 1b");
                }
                return new Settings(baud, latency, null, bytes);
            }
            if (!d.matches("\\d{1,7}(ms|s|m)")) {
                throw new IllegalArgumentException("--drop-after '" + dropAfter
                        + "' is neither a time (60s, 2m) nor a number of bytes (40000b)");
            }
            Duration t = duration("--drop-after", d);
            if (t.isZero()) {
                throw new IllegalArgumentException("--drop-after '" + dropAfter + "' must be more than 0");
            }
            return new Settings(baud, latency, t, 0);
        }
    }

    private final Link inner;
    private final Settings settings;
    private final PacedPipe in;
    private final PacedPipe out;
    private final Thread reader;
    private final Thread writer;
    private final AtomicLong crossed = new AtomicLong();
    private final ScheduledFuture<?> timedDrop;
    private volatile boolean closed;
    private volatile boolean dropped;
    private volatile IOException failure;
    private PacedPipe.Piece partial;
    private int partialAt;

    IridiumLine(Link inner, Settings settings) {
        this.inner = inner;
        this.settings = settings;
        long latency = settings.latency().toNanos();
        this.in = new PacedPipe(settings.baud(), latency);
        this.out = new PacedPipe(settings.baud(), latency);
        this.reader = new Thread(this::readLink, "glider-simulator-line-in");
        this.writer = new Thread(this::writeLink, "glider-simulator-line-out");
        reader.setDaemon(true);
        writer.setDaemon(true);
        reader.start();
        writer.start();
        timedDrop = settings.dropAfterTime() == null ? null
                : DROPS.schedule(() -> drop("after " + settings.dropAfterTime().toSeconds() + " s"),
                        settings.dropAfterTime().toMillis(), TimeUnit.MILLISECONDS);
    }

    /** True when the call ended because the line dropped it (not a hang-up by either end). */
    boolean dropped() {
        return dropped;
    }

    private void drop(String why) {
        if (closed || dropped) {
            return;
        }
        dropped = true;
        log.info("the simulated Iridium call dropped {} ({} bytes crossed)", why, crossed.get());
        inner.close();
        out.abandon();
    }

    private void count(int n) {
        if (settings.dropAfterBytes() > 0 && crossed.addAndGet(n) >= settings.dropAfterBytes()) {
            drop("after " + settings.dropAfterBytes() + " bytes");
        }
    }

    private void readLink() {
        byte[] buf = new byte[1024];
        try {
            while (!closed) {
                int n = inner.read(buf, 0, buf.length, 1000);
                if (n > 0) {
                    count(n);
                    in.put(buf, 0, n);
                }
            }
        } catch (IOException e) {
            log.debug("the simulated line's far end: {}", e.toString());
        } finally {
            in.end();
        }
    }

    private void writeLink() {
        try {
            while (true) {
                PacedPipe.Piece p = out.take();
                if (p.end()) {
                    return;
                }
                inner.write(p.bytes(), 0, p.bytes().length);
                inner.flush();
                count(p.bytes().length);
            }
        } catch (IOException e) {
            failure = e;
            out.abandon();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        if (partial == null) {
            try {
                partial = in.poll(timeoutMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return 0;
            }
            partialAt = 0;
            if (partial == null) {
                return 0;
            }
        }
        if (partial.end()) {
            throw new EOFException(dropped ? "the call dropped" : inner.describe() + " was closed by the other end");
        }
        int n = Math.min(len, partial.bytes().length - partialAt);
        System.arraycopy(partial.bytes(), partialAt, buffer, offset, n);
        partialAt += n;
        if (partialAt == partial.bytes().length) {
            partial = null;
        }
        return n;
    }

    @Override
    public void write(byte[] buffer, int offset, int len) throws IOException {
        if (dropped || failure != null) {
            throw new EOFException(dropped ? "the call dropped" : "the line failed: " + failure.getMessage());
        }
        out.put(buffer, offset, len);
    }

    @Override
    public void flush() {
        // pieces leave when they are due
    }

    @Override
    public String describe() {
        return inner.describe() + " (Iridium-like: " + settings.baud() + " baud, " + settings.latency().toMillis() + " ms)";
    }

    @Override
    public boolean hasCarrierLine() {
        return inner.hasCarrierLine();
    }

    @Override
    public boolean carrier() {
        return !dropped && inner.carrier();
    }

    /** Hangs up at once, dropping what has not crossed yet. */
    void cut() {
        closed = true;
        if (timedDrop != null) {
            timedDrop.cancel(false);
        }
        inner.close();
        out.abandon();
        out.end();
    }

    /** Lets what was written cross (a hang-up's last words arrive), then hangs up. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        out.end();
        try {
            writer.join(10_000 + settings.latency().toMillis() * 2); // a full buffer at 2,400 baud takes about 5 s
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        closed = true;
        if (timedDrop != null) {
            timedDrop.cancel(false);
        }
        inner.close();
        out.abandon();
    }
}
