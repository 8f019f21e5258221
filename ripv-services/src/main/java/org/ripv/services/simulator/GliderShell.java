package org.ripv.services.simulator;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.function.BooleanSupplier;
import java.util.function.LongFunction;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemException;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;

/**
 * The simulated vehicle's shell, whatever the link: reads a command line (echo, backspace,
 * Ctrl-C), answers PicoDOS's {@code dir}, {@code type}, {@code del}, {@code ys}, {@code yr},
 * {@code zs}, {@code zr}, {@code monitor}, {@code put} and {@code GO}, or hands the line to
 * {@link GliderDos} first when the simulator speaks it. How the vehicle is reached, and when it
 * dives, is {@link GliderSimulator}'s.
 */
final class GliderShell {
    static final String PROMPT = "C:\\>";
    private static final DateTimeFormatter DIR_TIME = DateTimeFormatter.ofPattern("MM-dd-yy  HH:mm", Locale.ROOT);

    private final Path dir;
    private final YmodemConfig ymodem;
    private final PlanState plan;
    private final Duration submerge;
    private final BooleanSupplier running;
    private final Runnable submerging;
    /** Null: the PicoDOS prompt at once (the default); else the Slocum surface dialog and GliderDOS. */
    private volatile GliderDos gliderDos;
    /** What the last GliderDOS command asked of the call (dive, call back); the conversation's thread only. */
    private GliderDos.End pendingEnd;

    /**
     * @param submerge   how long {@code GO} keeps it under water (said in its answer)
     * @param running    false once the simulator stops: a conversation then ends
     * @param submerging told at {@code GO}, before the link drops
     */
    GliderShell(Path dir, YmodemConfig ymodem, PlanState plan, Duration submerge, BooleanSupplier running,
                Runnable submerging) {
        this.dir = dir;
        this.ymodem = ymodem;
        this.plan = plan;
        this.submerge = submerge;
        this.running = running;
        this.submerging = submerging;
    }

    /** Writes the starting files into an empty directory. */
    static void seed(Path dir) throws IOException {
        try (var entries = Files.list(dir)) {
            if (entries.findAny().isPresent()) {
                return;
            }
        }
        Files.writeString(dir.resolve("GLIDER.CFG"), String.join("\r\n",
                "# glider configuration", "vehicle=SIM01", "dive_depth_m=200", "climb_depth_m=5",
                "pitch_deg=26", "surface_interval_s=900", ""), StandardCharsets.US_ASCII);
        Random random = new Random(42);
        for (int m = 1; m <= 2; m++) {
            StringBuilder log = new StringBuilder("% mission " + m + ": time depth temperature salinity\r\n");
            for (int i = 0; i < 400 * m; i++) {
                log.append(String.format(Locale.ROOT, "%d %.2f %.3f %.3f\r\n", i * 10, 100 + 90 * Math.sin(i / 20.0),
                        12 - i / 100.0 + random.nextGaussian() * 0.01, 35 + random.nextGaussian() * 0.02));
            }
            Files.writeString(dir.resolve("MISSION" + m + ".LOG"), log, StandardCharsets.US_ASCII);
        }
        byte[] binary = new byte[4096];
        random.nextBytes(binary);
        Files.write(dir.resolve("SENSOR.DAT"), binary);
    }

    void speakGliderDos(GliderDos g) {
        this.gliderDos = g;
    }

    /** The GliderDOS the shell speaks, or null for PicoDOS only. */
    GliderDos gliderDos() {
        return gliderDos;
    }

    String prompt() {
        GliderDos g = gliderDos;
        return g == null ? PROMPT : g.prompt();
    }

    /** How the last GliderDOS command ended the call (dive, call back), or null. */
    GliderDos.End end() {
        return pendingEnd;
    }

    void clearEnd() {
        pendingEnd = null;
    }

    /**
     * Answers commands until GO (true), or, when {@code until} is not 0, until that time has come
     * between two commands (true: the surface time is over). {@code chatter} is printed when the
     * line has been idle a while, as a vehicle's own output. With {@code renew} (nanoseconds), each
     * command moves {@code until} to that long after it: a time without input, as GliderDOS has.
     */
    boolean converse(ShellLink shell, long until, LongFunction<String> chatter, long renew)
            throws IOException {
        StringBuilder line = new StringBuilder();
        byte[] buf = new byte[1024];
        boolean lastWasCr = false;
        long lastChatter = System.nanoTime();
        while (running.getAsBoolean()) {
            if (until != 0 && line.isEmpty() && System.nanoTime() - until > 0) {
                return true;
            }
            int n = shell.read(buf, 0, buf.length, 1000);
            if (n == 0 && chatter != null && line.isEmpty() && System.nanoTime() - lastChatter > 10_000_000_000L) {
                lastChatter = System.nanoTime();
                shell.say(chatter.apply(until == 0 ? 0 : (until - lastChatter) / 1_000_000_000L) + "\r\n" + prompt());
            }
            for (int i = 0; i < n; i++) {
                int c = buf[i] & 0xFF;
                if (c == '\n' && lastWasCr) {
                    lastWasCr = false;
                    continue;
                }
                lastWasCr = c == '\r';
                if (c == '\r' || c == '\n') {
                    shell.say("\r\n");
                    shell.unread(buf, i + 1, n - i - 1);
                    String command = line.toString().trim();
                    line.setLength(0);
                    if (execute(shell, command)) {
                        return true;
                    }
                    if (renew > 0) {
                        until = System.nanoTime() + renew;
                    }
                    shell.say(prompt());
                    break;
                } else if (c == 8 || c == 0x7F) {
                    if (!line.isEmpty()) {
                        line.setLength(line.length() - 1);
                        shell.say("\b \b");
                    }
                } else if (c == SurfaceCountdown.CTRL_C && gliderDos != null) {
                    line.setLength(0); // GliderDOS drops the line typed so far and prompts again
                    shell.say("^C\r\n" + prompt());
                } else if (c >= 0x20 && c < 0x7F) {
                    line.append((char) c);
                    shell.write(new byte[] {(byte) c}, 0, 1); // echo, like the real vehicle
                }
                // other control bytes (CAN, stray ACKs after a transfer) are not echoed
            }
            shell.flush();
        }
        return false;
    }

    private boolean execute(ShellLink shell, String command) throws IOException {
        if (command.isEmpty()) {
            return false;
        }
        String[] words = command.split("\\s+");
        String verb = words[0].toUpperCase(Locale.ROOT);
        GliderDos g = gliderDos;
        if (g == null && verb.equals("PUT")) {
            shell.say(plan.put(words)); // a glider's put, at the simple shell too (docs/plans.md)
            return false;
        }
        GliderDos.Answer answer = g == null ? null : g.execute(verb, words);
        if (answer != null) {
            shell.say(answer.text());
            pendingEnd = answer.end();
            return answer.end() != null;
        }
        switch (verb) {
            case "DIR" -> shell.say(dir());
            case "TYPE" -> {
                Path file = file(shell, words);
                if (file != null) {
                    String text = new String(Files.readAllBytes(file), StandardCharsets.ISO_8859_1);
                    shell.say(text.replace("\r\n", "\n").replace("\n", "\r\n") + (text.endsWith("\n") ? "" : "\r\n"));
                }
            }
            case "DEL" -> {
                Path file = file(shell, words);
                if (file != null) {
                    Files.delete(file);
                }
            }
            case "YS" -> send(shell, words);
            case "YR" -> receive(shell);
            case "ZS" -> zsend(shell, words);
            case "ZR" -> shell.say("\r\n" + Lrzsz.receive(shell, dir) + "\r\n");
            case "GO" -> {
                submerging.run(); // from now on, before the link drops
                shell.say("Mission started; submerging for " + submerge.toSeconds() + " s\r\n");
                pendingEnd = new GliderDos.Resume("GO");
                return true;
            }
            case "MONITOR" -> monitor(shell, words);
            case "HELP", "?" -> shell.say("dir, type NAME, del NAME, ys NAME..., yr, zs NAME..., zr, monitor [SECONDS], go\r\n");
            default -> shell.say("Bad command or file name\r\n");
        }
        return false;
    }

    /**
     * {@code monitor [SECONDS]}: prints a depth line every 250 ms until Ctrl-C or the time is up
     * (default 60 s), like a glider's sensor report: a command that only an interrupt stops.
     */
    private void monitor(ShellLink shell, String[] words) throws IOException {
        long seconds = 60;
        if (words.length > 1) {
            try {
                seconds = Math.min(3600, Long.parseLong(words[1]));
            } catch (NumberFormatException e) {
                shell.say("usage: monitor [SECONDS]\r\n");
                return;
            }
        }
        long end = System.nanoTime() + seconds * 1_000_000_000L;
        byte[] keys = new byte[64];
        for (int i = 0; running.getAsBoolean() && System.nanoTime() - end < 0; i++) {
            int n = shell.read(keys, 0, keys.length, 250);
            for (int k = 0; k < n; k++) {
                if (keys[k] == 3) {
                    shell.say("^C\r\n");
                    return;
                }
            }
            shell.say(String.format(Locale.ROOT, "m_depth %.2f m\r\n", 5 + 3 * Math.sin(i / 8.0)));
        }
    }

    private Path file(ShellLink shell, String[] words) throws IOException {
        if (words.length != 2) {
            shell.say("Required parameter missing\r\n");
            return null;
        }
        Path file = resolve(words[1]);
        if (file == null) {
            shell.say("File not found - " + words[1] + "\r\n");
        }
        return file;
    }

    /** The file of that name, matched without regard to case as on FAT; null if none. */
    private Path resolve(String name) throws IOException {
        try {
            FileNames.requirePlain(name);
        } catch (IllegalArgumentException e) {
            return null;
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir)) {
            for (Path p : files) {
                if (Files.isRegularFile(p) && p.getFileName().toString().equalsIgnoreCase(name)) {
                    return p;
                }
            }
        }
        return null;
    }

    private String dir() throws IOException {
        StringBuilder b = new StringBuilder(" Volume in drive C is GLIDER\r\n Directory of C:\\\r\n\r\n");
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> stream = Files.newDirectoryStream(dir)) {
            for (Path p : stream) {
                if (Files.isRegularFile(p) && !p.getFileName().toString().startsWith(".")) {
                    files.add(p);
                }
            }
        }
        files.sort(null);
        long total = 0;
        for (Path p : files) {
            long size = Files.size(p);
            total += size;
            LocalDateTime t = LocalDateTime.ofInstant(Files.getLastModifiedTime(p).toInstant(), ZoneId.systemDefault());
            b.append(String.format(Locale.ROOT, "%-12s %10d  %s\r\n", p.getFileName(), size, DIR_TIME.format(t)));
        }
        b.append(String.format(Locale.ROOT, "%9d file(s) %12d bytes\r\n", files.size(), total));
        return b.toString();
    }

    /** The files {@code verb NAME...} names, or null when it names none or one that is not there (said). */
    private List<Path> files(ShellLink shell, String[] words, String verb) throws IOException {
        if (words.length < 2) {
            shell.say("usage: " + verb + " NAME...\r\n");
            return null;
        }
        List<Path> files = new ArrayList<>();
        for (int i = 1; i < words.length; i++) {
            Path p = resolve(words[i]);
            if (p == null) {
                shell.say("File not found - " + words[i] + "\r\n");
                return null;
            }
            files.add(p);
        }
        return files;
    }

    private void send(ShellLink shell, String[] words) throws IOException {
        List<Path> paths = files(shell, words, "ys");
        if (paths == null) {
            return;
        }
        List<SendFile> files = new ArrayList<>();
        for (Path p : paths) {
            files.add(SendFile.of(p));
        }
        try {
            new YmodemSender(shell, ymodem, null).sendBatch(files);
            shell.say("\r\n" + files.size() + " file(s) sent\r\n");
        } catch (YmodemException e) {
            shell.say("\r\nYMODEM send failed: " + e.getMessage() + "\r\n");
        }
    }

    /** {@code zs NAME...}: lrzsz's sz sends the files (names matched without regard to case). */
    private void zsend(ShellLink shell, String[] words) throws IOException {
        List<Path> paths = files(shell, words, "zs");
        if (paths == null) {
            return;
        }
        List<String> names = new ArrayList<>();
        for (Path p : paths) {
            names.add(p.getFileName().toString());
        }
        shell.say("\r\n" + Lrzsz.send(shell, dir, names) + "\r\n");
    }

    private void receive(ShellLink shell) throws IOException {
        try {
            List<FileHeader> got = new YmodemReceiver(shell, ymodem, null).receiveBatch(new DirectorySink(dir));
            shell.say("\r\n" + got.size() + " file(s) received\r\n");
        } catch (YmodemException e) {
            shell.say("\r\nYMODEM receive failed: " + e.getMessage() + "\r\n");
        }
    }
}
