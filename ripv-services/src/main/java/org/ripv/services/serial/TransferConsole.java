package org.ripv.services.serial;

import java.util.List;
import java.util.Locale;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.TransferListener;

/**
 * A YMODEM transfer as the console shows it: one TRANSFER line when a file starts, one every few
 * seconds while it runs, one when it is complete; never the bytes themselves.
 */
final class TransferConsole implements TransferListener {
    private static final long EVERY_NANOS = 3_000_000_000L;

    private final VehicleConsole console;
    private final String user;
    private final String verb;
    private final String doneVerb;
    private long last;

    /** @param verb "receiving" or "sending" */
    TransferConsole(VehicleConsole console, String user, String verb) {
        this.console = console;
        this.user = user;
        this.verb = verb;
        this.doneVerb = verb.equals("receiving") ? "received" : "sent";
    }

    @Override
    public void started(FileHeader file) {
        last = System.nanoTime();
        console.transfer(user, verb + " " + file.name() + (file.length() >= 0 ? " (" + file.length() + " bytes)" : ""));
    }

    @Override
    public void progress(FileHeader file, long done) {
        long now = System.nanoTime();
        if (now - last > EVERY_NANOS) {
            last = now;
            String of = file.length() > 0 ? String.format(Locale.ROOT, " of %d (%.0f %%)", file.length(),
                    100.0 * done / file.length()) : "";
            console.transfer(user, verb + " " + file.name() + ": " + done + of + " bytes");
        }
    }

    @Override
    public void finished(FileHeader file) {
        console.transfer(user, doneVerb + " " + file.name() + " (" + Math.max(0, file.length()) + " bytes)");
    }

    @Override
    public void resumed(FileHeader file, long offset) {
        console.transfer(user, verb + " " + file.name() + " from byte " + offset + " (the rest of a dropped call's part)");
    }

    /** What a transfer tells as it goes: PROGRESS replies, the console's TRANSFER lines, then {@code ?status}. */
    static TransferListener listeners(ProgressReporter progress, VehicleConsole console, String user, String verb,
                                      TransferListener status) {
        return new Fan(List.of(progress, new TransferConsole(console, user, verb), status));
    }

    /** Tells each listener in turn, in the order a transfer's life calls them. */
    record Fan(List<TransferListener> each) implements TransferListener {
        @Override
        public void started(FileHeader file) {
            each.forEach(l -> l.started(file));
        }

        @Override
        public void progress(FileHeader file, long done) {
            each.forEach(l -> l.progress(file, done));
        }

        @Override
        public void resumed(FileHeader file, long offset) {
            each.forEach(l -> l.resumed(file, offset));
        }

        @Override
        public void finished(FileHeader file) {
            each.forEach(l -> l.finished(file));
        }
    }
}
