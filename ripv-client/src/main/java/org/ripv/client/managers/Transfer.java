package org.ripv.client.managers;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.LongSupplier;

/**
 * One file moving between the operator's computer and the server (FIM panel's progress bars).
 * Progress fields are updated on the model's thread; {@link #cancel()} may be called from any
 * thread and is seen by the transferring thread at the next chunk.
 */
public final class Transfer {
    /** Which way the file moves. */
    public enum Direction { UPLOAD, DOWNLOAD }

    /** Where the transfer is. */
    public enum State { RUNNING, DONE, FAILED, CANCELLED }

    private final long id;
    private final Direction direction;
    private final String name;
    private final Path local;
    private final AtomicBoolean cancelRequested = new AtomicBoolean();
    private long done;
    private long total;
    private State state = State.RUNNING;
    private String detail = "";
    private final LongSupplier clock;
    private long startNanos = -1;
    private long lastNanos;
    private boolean nameTaken;
    private boolean asked;

    Transfer(long id, Direction direction, String name, Path local, long total) {
        this(id, direction, name, local, total, System::nanoTime);
    }

    /** With the clock rate and ETA are measured by (tests give their own). */
    Transfer(long id, Direction direction, String name, Path local, long total, LongSupplier nanoClock) {
        this.id = id;
        this.direction = direction;
        this.name = name;
        this.local = local;
        this.total = total;
        this.clock = nanoClock;
    }

    /** Bytes per second since the first byte, or 0 before there is a measure. */
    public double rate() {
        if (startNanos < 0 || lastNanos <= startNanos || done <= 0) {
            return 0;
        }
        return done * 1e9 / (lastNanos - startNanos);
    }

    /** Seconds until done at the rate so far, or -1 when unknown (no rate, no total, finished). */
    public long etaSeconds() {
        double r = rate();
        if (finished() || r <= 0 || total <= 0) {
            return -1;
        }
        return (long) Math.ceil((total - done) / r);
    }

    /** "45%  1.2 MB / 2.6 MB  310 KB/s  0:05 left": what the FIM progress bar says. */
    public String progressText() {
        if (finished()) {
            return state.name().toLowerCase(Locale.ROOT);
        }
        if (percent() < 0) {
            return "starting";
        }
        StringBuilder b = new StringBuilder().append(percent()).append("%  ").append(size(done)).append(" / ").append(size(total));
        if (rate() > 0) {
            b.append("  ").append(size((long) rate())).append("/s");
        }
        long eta = etaSeconds();
        if (eta >= 0) {
            b.append("  ").append(eta / 60).append(':').append(String.format(Locale.ROOT, "%02d", eta % 60)).append(" left");
        }
        return b.toString();
    }

    /** "1.2 MB", "310 KB", "12 B". */
    public static String size(long bytes) {
        if (bytes < 1024) {
            return bytes + " B";
        }
        if (bytes < 1024 * 1024) {
            return String.format(Locale.ROOT, "%.0f KB", bytes / 1024.0);
        }
        return String.format(Locale.ROOT, "%.1f MB", bytes / (1024.0 * 1024));
    }

    /** An upload the server refused because the store has a file of that name (FILE_EXISTS). */
    public boolean nameTaken() {
        return nameTaken;
    }

    /**
     * True the first time it is called for a refused upload: so that of all the windows' FIM panels
     * only one asks the operator what to do. On the model's thread.
     */
    public boolean claimQuestion() {
        if (!nameTaken || asked) {
            return false;
        }
        asked = true;
        return true;
    }

    public long id() {
        return id;
    }

    public Direction direction() {
        return direction;
    }

    /** The file's name on the server. */
    public String name() {
        return name;
    }

    /** The file on this computer (for a download: the directory until it completes). */
    public Path local() {
        return local;
    }

    public long done() {
        return done;
    }

    public long total() {
        return total;
    }

    /** 0–100, or -1 while the total is unknown. */
    public int percent() {
        return total <= 0 ? (state == State.DONE ? 100 : -1) : (int) Math.min(100, done * 100 / total);
    }

    public State state() {
        return state;
    }

    /** The error message or the final path, for the tooltip. */
    public String detail() {
        return detail;
    }

    public boolean finished() {
        return state != State.RUNNING;
    }

    /** Asks the transfer to stop at the next chunk; a partial download is deleted. */
    public void cancel() {
        cancelRequested.set(true);
    }

    public boolean cancelRequested() {
        return cancelRequested.get();
    }

    void progress(long doneBytes, long totalBytes) {
        long now = clock.getAsLong();
        if (startNanos < 0) {
            startNanos = now; // the clock starts with the first report (0 of N)
        }
        lastNanos = now;
        this.done = doneBytes;
        this.total = totalBytes;
    }

    void nameTaken(boolean taken) {
        this.nameTaken = taken;
    }

    void finish(State s, String why) {
        this.state = s;
        this.detail = why == null ? "" : why;
    }

    @Override
    public String toString() {
        return (direction == Direction.UPLOAD ? "UL " : "DL ") + name + " " + state
                + (percent() >= 0 ? " " + percent() + "%" : "") + (detail.isEmpty() ? "" : " " + detail);
    }
}
