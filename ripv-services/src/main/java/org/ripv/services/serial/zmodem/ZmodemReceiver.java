package org.ripv.services.serial.zmodem;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.TransferListener;

/**
 * Receives a ZMODEM batch (the vehicle runs {@code sz NAME…}): answers ZRQINIT with ZRINIT
 * (full duplex, CRC-32), takes each ZFILE, starts it where {@link ResumeStore} says (ZRPOS),
 * takes its data subpackets, and answers a damaged one with ZRPOS at the last good byte.
 *
 * <p>What arrived is written to the part as it is checked; a call that drops keeps it. A peer
 * that sends beyond the size it announced, or whose ZEOF disagrees with it, loses the part.
 */
public final class ZmodemReceiver extends ZmodemPeer<ZmodemReceiver> {
    /** One file received whole. */
    public record Received(FileHeader file, Path path, long resumedAt, String note) {
    }

    /** How many ZRINITs, ZRPOSs or damaged subpackets before a transfer gives up. */
    static final int MAX_ERRORS = 20;
    /** Lies about positions (a ZDATA or ZEOF elsewhere than asked) a peer is allowed before it is not believed. */
    static final int MAX_OUT_OF_STEP = 10;
    /** Bytes that are no frame tolerated outside a file's data (a shell's echo, a banner). */
    static final int BETWEEN_FILES_GARBAGE = 8192;

    public ZmodemReceiver(ByteLink link, long timeoutMillis, TransferListener listener) {
        super(link, timeoutMillis, listener);
    }

    @Override
    ZmodemReceiver self() {
        return this;
    }

    /**
     * Receives files until the sender's ZFIN; complete ones are moved to {@code into}.
     *
     * @throws ZmodemException on a timeout, too many errors, the peer's abort or lies; a file cut
     *                         short keeps its part in {@code store} unless the peer lied
     */
    public List<Received> receive(ResumeStore store, Path into) throws IOException {
        List<Received> got = new ArrayList<>();
        ZHeader h = first();
        int errors = 0;
        while (true) {
            checkCancel();
            switch (h.type()) {
                case Zmodem.ZRQINIT -> zrinit();
                case Zmodem.ZSINIT -> {
                    in.data(buf, h.crc32(), timeoutMillis); // the attention string: we never need to interrupt the sender
                    out.hex(ZHeader.position(Zmodem.ZACK, 0));
                }
                case Zmodem.ZFILE -> {
                    Received r = file(h, store, into);
                    if (r != null) {
                        got.add(r);
                    }
                    zrinit();
                }
                case Zmodem.ZFIN -> {
                    out.hex(ZHeader.position(Zmodem.ZFIN, 0));
                    in.overAndOut(Math.min(timeoutMillis, 1000));
                    return got;
                }
                case Zmodem.ZCOMMAND -> {
                    // a vehicle never gets to run commands on the service's host
                    abort();
                    throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle sent ZCOMMAND; refused");
                }
                default -> {
                    if (++errors > MAX_ERRORS) {
                        throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle keeps sending "
                                + Zmodem.name(h.type()) + " between files");
                    }
                    zrinit();
                }
            }
            h = next(() -> zrinit(), "the next file or ZFIN");
        }
    }

    private void zrinit() throws IOException {
        out.hex(ZHeader.flags(Zmodem.ZRINIT, Zmodem.CANFDX | Zmodem.CANOVIO | Zmodem.CANFC32, 0, 0, 0));
    }

    /**
     * The sender's first header. ZRINIT goes out only after a silence: sz announces itself with
     * ZRQINIT, and a ZRINIT sent before the vehicle's shell has started sz would be read by the
     * shell as the next command line.
     */
    private ZHeader first() throws IOException {
        long deadline = System.nanoTime() + startTimeoutMillis * 1_000_000L;
        while (true) {
            checkCancel();
            try {
                return in.header(Math.min(timeoutMillis, 1000), refusal);
            } catch (ZFrameReader.Timeout e) {
                if (System.nanoTime() - deadline > 0) {
                    throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle did not start sending within "
                            + startTimeoutMillis / 1000 + " s");
                }
                zrinit();
            }
        }
    }

    @FunctionalInterface
    private interface Nudge {
        void send() throws IOException;
    }

    /** The next header, nudging the sender on each silence, up to {@link #MAX_ERRORS} times. */
    private ZHeader next(Nudge nudge, String waitingFor) throws IOException {
        for (int tries = 0; ; tries++) {
            checkCancel();
            try {
                return in.header(timeoutMillis, null);
            } catch (ZFrameReader.Timeout e) {
                if (tries >= MAX_ERRORS / 4) {
                    throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle went silent while we waited for "
                            + waitingFor + " (" + (tries + 1) + " x " + timeoutMillis + " ms)");
                }
                nudge.send();
            }
        }
    }

    private FileHeader fileInfo(ZHeader h) throws IOException {
        for (int tries = 0; tries < MAX_ERRORS; tries++) {
            ZFrameReader.Subpacket s = in.data(buf, h.crc32(), timeoutMillis);
            if (s.crcOk()) {
                return parseInfo(buf, s.length());
            }
            out.hex(ZHeader.position(Zmodem.ZNAK, 0));
            ZHeader again = next(() -> out.hex(ZHeader.position(Zmodem.ZNAK, 0)), "ZFILE again");
            if (again.type() != Zmodem.ZFILE) {
                throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle answered a damaged ZFILE with "
                        + again);
            }
            h = again;
        }
        throw new ZmodemException(ZmodemException.Kind.LINE, "the ZFILE header kept arriving damaged");
    }

    /** {@code name NUL size mtime(octal) mode(octal) …}: the ZFILE subpacket. */
    static FileHeader parseInfo(byte[] b, int n) throws ZmodemException {
        int nul = 0;
        while (nul < n && b[nul] != 0) {
            nul++;
        }
        String sent = new String(b, 0, nul, StandardCharsets.ISO_8859_1);
        String name;
        try {
            name = FileNames.requirePlain(FileNames.baseName(sent));
        } catch (IllegalArgumentException e) {
            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle offered a file with a bad name: " + e.getMessage());
        }
        int end = nul + 1;
        while (end < n && b[end] != 0) {
            end++;
        }
        String[] f = nul + 1 < n ? new String(b, nul + 1, end - nul - 1, StandardCharsets.ISO_8859_1).trim().split("\\s+")
                : new String[0];
        try {
            long length = f.length > 0 && !f[0].isEmpty() ? Long.parseLong(f[0]) : -1;
            long mtime = f.length > 1 ? Long.parseLong(f[1], 8) : 0;
            int mode = f.length > 2 ? Integer.parseInt(f[2], 8) : 0;
            if (length < -1) {
                throw new NumberFormatException("negative");
            }
            return new FileHeader(name, length, mtime, mode);
        } catch (NumberFormatException e) {
            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle's ZFILE for '" + name
                    + "' has a size or time that is not a number: '" + String.join(" ", f) + "'");
        }
    }

    /** One file: null when it was skipped. */
    private Received file(ZHeader h, ResumeStore store, Path into) throws IOException {
        FileHeader file = fileInfo(h);
        ResumeStore.Start start = store.offer(file);
        long pos = start.offset();
        listener.started(file);
        if (pos > 0) {
            listener.resumed(file, pos);
        }
        long from = pos;
        // After a ZRPOS, what the sender had already streamed into the link's buffers (a TCP
        // link holds hundreds of KB) arrives before its new ZDATA and is skipped: during a file
        // that is expected, up to the file's size and some, as lrzsz allows about a second's worth
        in.garbageLimit((int) Math.min(Integer.MAX_VALUE, Math.max(BETWEEN_FILES_GARBAGE, file.length() + 65_536)));
        try (OutputStream o = store.open(file, pos)) {
            pos = data(file, pos, o);
        } catch (ZmodemException e) {
            throw finish(store, file, from, e.kind() == ZmodemException.Kind.LINE, e);
        } catch (IOException e) {
            throw finish(store, file, from, true, e);
        }
        in.garbageLimit(BETWEEN_FILES_GARBAGE);
        Path target = into.resolve(file.name());
        store.complete(file.name(), target);
        listener.finished(file);
        return new Received(file, target, from, start.note());
    }

    /** A file was cut short: keep its sound part for a resume, or drop it when the peer is not to be believed. */
    private IOException finish(ResumeStore store, FileHeader file, long from, boolean keep, IOException e) {
        try {
            long have = store.partLength(file.name());
            if (keep && have > 0) {
                store.interrupted(file.name(), from, have);
            } else {
                store.discard(file.name());
            }
        } catch (IOException ignored) {
            e.addSuppressed(ignored);
        }
        return e;
    }

    /** The data of one file from {@code pos}; returns its length at ZEOF. */
    private long data(FileHeader file, long pos, OutputStream o) throws IOException {
        long p = pos;
        int errors = 0;
        int outOfStep = 0;
        out.hex(ZHeader.position(Zmodem.ZRPOS, p));
        while (true) {
            long at = p;
            ZHeader h = next(() -> out.hex(ZHeader.position(Zmodem.ZRPOS, at)), "data of " + file.name());
            switch (h.type()) {
                case Zmodem.ZDATA -> {
                    if (h.position() != p) {
                        if (++outOfStep > MAX_OUT_OF_STEP) {
                            abort();
                            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle keeps sending "
                                    + file.name() + " from byte " + h.position() + " when asked for byte " + p);
                        }
                        out.hex(ZHeader.position(Zmodem.ZRPOS, p));
                        continue;
                    }
                    long before = p;
                    p = subpackets(file, p, o, h.crc32());
                    if (p < 0) {
                        p = -p - 1; // a damaged subpacket: back to the last good byte
                        if (++errors > MAX_ERRORS) {
                            throw new ZmodemException(ZmodemException.Kind.LINE, "too many damaged subpackets in "
                                    + file.name() + " (last good byte " + p + ")");
                        }
                        out.hex(ZHeader.position(Zmodem.ZRPOS, p));
                    } else if (p > before) {
                        errors = 0;
                    }
                }
                case Zmodem.ZEOF -> {
                    if (h.position() != p) {
                        if (++outOfStep > MAX_OUT_OF_STEP) {
                            abort();
                            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle ends " + file.name()
                                    + " at byte " + h.position() + " but sent " + p);
                        }
                        continue; // a stale ZEOF from before our ZRPOS: the spec says ignore it
                    }
                    if (file.length() >= 0 && p != file.length()) {
                        abort();
                        throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle announced " + file.name()
                                + " as " + file.length() + " bytes but ended it at " + p);
                    }
                    return p;
                }
                case Zmodem.ZFILE -> {
                    fileInfo(h); // our ZRPOS was lost: it repeats the offer
                    out.hex(ZHeader.position(Zmodem.ZRPOS, p));
                }
                case Zmodem.ZNAK, Zmodem.ZRQINIT -> out.hex(ZHeader.position(Zmodem.ZRPOS, p));
                case Zmodem.ZFIN, Zmodem.ZSKIP, Zmodem.ZABORT, Zmodem.ZFERR, Zmodem.ZCAN ->
                        throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle stopped sending " + file.name()
                                + " at byte " + p + " (" + Zmodem.name(h.type()) + ")");
                default -> {
                    if (++errors > MAX_ERRORS) {
                        throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "unexpected " + h + " during " + file.name());
                    }
                    out.hex(ZHeader.position(Zmodem.ZRPOS, p));
                }
            }
        }
    }

    /**
     * Subpackets after a ZDATA until its frame ends. Returns the new position, or
     * {@code -(position + 1)} after a damaged subpacket.
     */
    private long subpackets(FileHeader file, long pos, OutputStream o, boolean crc32) throws IOException {
        long p = pos;
        while (true) {
            checkCancel();
            ZFrameReader.Subpacket s;
            try {
                s = in.data(buf, crc32, timeoutMillis);
            } catch (ZFrameReader.Timeout e) {
                return -p - 1;
            }
            if (!s.crcOk()) {
                return -p - 1;
            }
            if (file.length() >= 0 && p + s.length() > file.length()) {
                abort();
                throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle sent more of " + file.name()
                        + " than the " + file.length() + " bytes it announced");
            }
            o.write(buf, 0, s.length());
            p += s.length();
            listener.progress(file, p);
            switch (s.end()) {
                case Zmodem.ZCRCW -> {
                    o.flush();
                    out.hex(ZHeader.position(Zmodem.ZACK, p));
                    return p;
                }
                case Zmodem.ZCRCQ -> out.hex(ZHeader.position(Zmodem.ZACK, p));
                case Zmodem.ZCRCE -> {
                    return p;
                }
                default -> { } // ZCRCG: more follows
            }
        }
    }
}
