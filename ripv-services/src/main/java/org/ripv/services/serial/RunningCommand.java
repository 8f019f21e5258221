package org.ripv.services.serial;

import org.ripv.messages.Progress;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.TransferListener;

/**
 * What a link is doing now, for {@code ?status} and {@code ?mailboxes}: a plain command
 * ("running 'dir' for alice, 3 s") or a transfer ("ymodem:get MISSION1.LOG 40 % ETA 1:12,
 * 11.2 kB/s, file 2 of 5"). Written by the command's thread, read by any.
 */
final class RunningCommand {
    private volatile String command;
    private volatile String user;
    private volatile long since;
    private volatile Transfer transfer;

    /** A transfer's latest state. */
    private record Transfer(String verb, int files, int index, Progress progress) {}

    void start(String commandLine, String byUser) {
        transfer = null;
        user = byUser;
        since = System.nanoTime();
        command = commandLine;
    }

    void end() {
        command = null;
        transfer = null;
    }

    /**
     * A listener for a transfer of {@code files} files (-1: unknown) under {@code verb}
     * ({@code ymodem:get}, {@code ymodem:put}).
     */
    TransferListener transfer(String verb, int files) {
        return new TransferListener() {
            private long fileStart;
            private long base;
            private int index;

            @Override
            public void started(FileHeader file) {
                fileStart = System.nanoTime();
                base = 0;
                index++;
                transfer = new Transfer(verb, files, index, new Progress(file.name(), 0, file.length(), 0));
            }

            @Override
            public void progress(FileHeader file, long done) {
                double seconds = (System.nanoTime() - fileStart) / 1e9;
                transfer = new Transfer(verb, files, index, new Progress(file.name(), done, file.length(),
                        seconds > 0.2 ? (done - base) / seconds : 0));
            }

            @Override
            public void resumed(FileHeader file, long offset) {
                base = offset;
            }

            @Override
            public void finished(FileHeader file) {
                Transfer t = transfer;
                transfer = new Transfer(verb, files, index, new Progress(file.name(), Math.max(0, file.length()),
                        file.length(), t == null ? 0 : t.progress().ratePerSecond()));
            }
        };
    }

    /** What runs, or null when nothing does. */
    String describe() {
        String c = command;
        if (c == null) {
            return null;
        }
        Transfer t = transfer;
        if (t == null) {
            long s = (System.nanoTime() - since) / 1_000_000_000L;
            return (c.startsWith("ymodem:") || c.startsWith("zmodem:") ? c + " starting" : "running '" + c + "'") + " for " + user + ", " + s + " s";
        }
        Progress p = t.progress();
        String pct = p.shortText();
        return t.verb() + " " + p.what() + (pct.isEmpty() ? " " + p.done() + " bytes" : " " + pct)
                + (p.rateText().isEmpty() ? "" : ", " + p.rateText())
                + (t.files() > 1 ? ", file " + t.index() + " of " + t.files() : "") + " for " + user;
    }
}
