package org.ripv.client.managers;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicBoolean;

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

    Transfer(long id, Direction direction, String name, Path local, long total) {
        this.id = id;
        this.direction = direction;
        this.name = name;
        this.local = local;
        this.total = total;
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
        this.done = doneBytes;
        this.total = totalBytes;
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
