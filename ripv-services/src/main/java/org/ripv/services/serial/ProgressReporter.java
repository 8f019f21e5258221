package org.ripv.services.serial;

import java.util.Locale;
import org.ripv.messages.Progress;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.TransferListener;

/** Turns transfer events into PROGRESS replies, at most a few per second. */
final class ProgressReporter implements TransferListener {
    private final Request request;
    private final String verb;
    private final long start = System.nanoTime();
    private long fileStart;
    private long base;
    private long lastSent;

    ProgressReporter(Request request, String verb) {
        this.request = request;
        this.verb = verb;
    }

    @Override
    public void started(FileHeader file) {
        fileStart = System.nanoTime();
        base = 0;
        send(file, 0);
    }

    @Override
    public void progress(FileHeader file, long done) {
        long now = System.nanoTime();
        if (now - lastSent > 500_000_000L) {
            send(file, done);
        }
    }

    @Override
    public void finished(FileHeader file) {
        send(file, Math.max(0, file.length()));
    }

    @Override
    public void resumed(FileHeader file, long offset) {
        base = offset;
        send(file, offset);
    }

    private void send(FileHeader file, long done) {
        lastSent = System.nanoTime();
        double seconds = Math.max(1e-3, (lastSent - fileStart) / 1e9);
        request.progress(verb + " " + file.name(), new Progress(file.name(), done, file.length(), Math.max(0, done - base) / seconds));
    }

    String summary(long bytes) {
        double seconds = Math.max(1e-3, (System.nanoTime() - start) / 1e9);
        return String.format(Locale.ROOT, "%.1f s (%.0f bytes/s)", seconds, bytes / seconds);
    }
}
