package org.ripv.services.simulator;

import java.io.EOFException;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import org.ripv.services.serial.Link;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialLink;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemException;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A PicoDOS-like glider for tests and demos: a {@code C:\>} prompt, echo of what it is sent,
 * and the commands {@code dir}, {@code del NAME}, {@code type NAME}, {@code ys NAME…} (send by
 * YMODEM), {@code yr} (receive by YMODEM), {@code monitor [SECONDS]} (prints until Ctrl-C) and {@code GO}, which "submerges" it: it stops
 * answering and, on TCP, drops the connection and refuses new ones until it surfaces.
 *
 * <p>It serves one connection at a time, on a TCP port ({@link #listen}) or on a serial device
 * or pseudo-terminal ({@link #attach}), or calls a shore station again and again ({@link #call})
 * with a {@link SurfaceDialog} on each call. Its files live in one directory. {@code zs} and
 * {@code zr} run lrzsz ({@link Lrzsz}). {@link #speakGliderDos} makes each call a Slocum's
 * surfacing ({@link SurfaceCountdown}, {@link GliderDos}); {@link #overLine} makes TCP calls
 * Iridium-like ({@link IridiumLine}).
 */
public final class GliderSimulator implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(GliderSimulator.class);
    static final String PROMPT = "C:\\>";
    private static final DateTimeFormatter DIR_TIME = DateTimeFormatter.ofPattern("MM-dd-yy  HH:mm", Locale.ROOT);

    private final Path dir;
    private final Duration submerge;
    private final YmodemConfig ymodem;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile boolean running = true;
    private volatile ServerSocket serverSocket;
    private volatile Link current;
    private volatile boolean submerged;
    private int port;
    private volatile int calls;
    private Thread thread;
    private InetAddress bindAddress = InetAddress.getLoopbackAddress();
    /** Null: the PicoDOS prompt at once (the default); else the Slocum surface dialog and GliderDOS. */
    private volatile GliderDos gliderDos;
    private volatile SurfaceTrouble trouble = SurfaceTrouble.NONE;
    /** What its plan (goto_l10.ma, put values) makes its dialog print. */
    private final PlanState plan;
    private volatile Duration surfaceWait = Duration.ofSeconds(60);
    private volatile IridiumLine.Settings line = IridiumLine.Settings.NONE;
    private volatile String name = "sim01";
    /** What the last GliderDOS command asked of the call (dive, call back); the conversation's thread only. */
    private GliderDos.End pendingEnd;
    /** A dropped Iridium-like call is dialled again after this long, without a dive. */
    static final Duration REDIAL = Duration.ofSeconds(2);

    /**
     * @param dir      the vehicle's file system; seeded with mission logs and a config file if empty
     * @param submerge how long {@code GO} keeps it under water
     */
    public GliderSimulator(Path dir, Duration submerge, YmodemConfig ymodem) throws IOException {
        this.dir = Files.createDirectories(dir);
        this.plan = new PlanState(this.dir);
        this.submerge = submerge;
        this.ymodem = ymodem;
        seed(this.dir);
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

    public Path directory() {
        return dir;
    }

    /** Serves TCP connections on {@code port} (0: any free port). Returns the bound port. */
    public synchronized int listen(int listenPort) throws IOException {
        serverSocket = bind(listenPort);
        port = serverSocket.getLocalPort();
        thread = new Thread(this::serveTcp, "glider-simulator-" + port);
        thread.setDaemon(true);
        thread.start();
        log.info("glider simulator listening on port {} with files in {}", port, dir);
        return port;
    }

    /** Serves the serial device or pseudo-terminal at {@code path}. */
    public synchronized void attach(String path) throws IOException {
        Link link = SerialLink.open(LinkSettings.defaults(path));
        current = link;
        thread = new Thread(() -> serveTty(link), "glider-simulator-tty");
        thread.setDaemon(true);
        thread.start();
        log.info("glider simulator on {} with files in {}", path, dir);
    }

    private ServerSocket bind(int port) throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        s.bind(new InetSocketAddress(bindAddress, port));
        return s;
    }

    /**
     * The address {@link #listen} binds to: loopback unless set (a simulated vehicle is for this
     * machine; {@code --bind} widens it). Null means every interface. Call before {@code listen}.
     */
    public synchronized GliderSimulator bindTo(InetAddress address) {
        this.bindAddress = address;
        return this;
    }

    /**
     * Speaks GliderDOS: on every call or connection the surface dialog, then the keys and a
     * countdown of {@code wait} that resumes the mission (a dive) unless a key comes; Ctrl-C gives
     * the GliderDOS prompt, where {@code wait} without input resumes it too. {@code minute} is how
     * long a {@code callback} minute lasts. Call before {@code listen}, {@code attach} or {@code call}.
     */
    public synchronized GliderSimulator speakGliderDos(Duration wait, Duration minute) {
        this.surfaceWait = wait;
        this.gliderDos = new GliderDos(dir, minute);
        return this;
    }

    /**
     * Trouble on demand in the GliderDOS dialog: an abort on each of {@code abortCalls} (1 for the
     * first call), a leak from call {@code leakFrom} on (0: none). Call before {@code call}.
     */
    public synchronized GliderSimulator trouble(Set<Integer> abortCalls, int leakFrom) {
        this.trouble = new SurfaceTrouble(abortCalls, leakFrom);
        return this;
    }

    /** The vehicle's name in its surface dialog on {@code listen} and {@code attach} ({@code call} names its own). */
    public synchronized GliderSimulator named(String vehicleName) {
        this.name = vehicleName;
        return this;
    }

    /** Makes every TCP call Iridium-like (pace, latency, drops). Call before {@code listen} or {@code call}. */
    synchronized GliderSimulator overLine(IridiumLine.Settings settings) {
        this.line = settings;
        return this;
    }

    /**
     * Makes every TCP call Iridium-like: {@code baud} each way (0: unpaced), {@code latency} each
     * way, dropped after {@code dropAfter} ({@code 60s}, {@code 40000b}; null: never).
     */
    public GliderSimulator overLine(int baud, Duration latency, String dropAfter) {
        return overLine(IridiumLine.Settings.withDrop(baud, latency, dropAfter));
    }

    private Link wrap(Link link) {
        IridiumLine.Settings s = line;
        return s.any() ? new IridiumLine(link, s) : link;
    }

    private String prompt() {
        GliderDos g = gliderDos;
        return g == null ? PROMPT : g.prompt();
    }

    private void serveTcp() {
        try {
            while (running) {
                Socket socket;
                try {
                    socket = serverSocket.accept();
                } catch (IOException e) {
                    if (!running) {
                        return;
                    }
                    throw e;
                }
                try {
                    Duration away = null;
                    Link link = wrap(new TcpLink(socket));
                    current = link;
                    try {
                        away = session(link);
                        if (away != null) {
                            // under water nobody can connect: shut the door before the caller sees the
                            // link drop, or a caller quick to dial again got in before it closed
                            serverSocket.close();
                        }
                    } finally {
                        current = null;
                        link.close();
                    }
                    if (away != null) {
                        submerged = true;
                        dive(away);
                        if (running) {
                            serverSocket = bind(port);
                            log.info("surfaced; listening on port {} again", port);
                        }
                    }
                } catch (EOFException e) {
                    log.info("connection closed: {}", e.getMessage());
                } catch (IOException e) {
                    log.warn("connection failed: {}", e.toString());
                }
            }
        } catch (IOException e) {
            log.error("simulator stopped: {}", e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            stopped.countDown();
        }
    }

    private void serveTty(Link link) {
        try {
            while (running) {
                Duration away = session(link);
                if (away != null) {
                    submerged = true;
                    dive(away);
                    // under water the modem hears nothing: drop what arrived meanwhile
                    byte[] junk = new byte[4096];
                    while (link.read(junk, 0, junk.length, 1) > 0) {
                        log.debug("dropped input that arrived while submerged");
                    }
                }
            }
        } catch (IOException e) {
            log.warn("tty session ended: {}", e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            link.close();
            stopped.countDown();
        }
    }

    private void dive(Duration time) throws InterruptedException {
        log.info("submerged for {} s", time.toSeconds());
        try {
            // the glider is away for this long; stop() wakes it early
            stopped.await(time.toMillis(), TimeUnit.MILLISECONDS);
        } finally {
            submerged = false;
        }
    }

    /**
     * Calls a shore station ({@code listen://} link) like a glider: connects, prints the surface
     * dialog, answers commands for {@code surfaceTime} (or until GO), hangs up, dives for
     * {@code diveTime}, and calls again. A refused or failed call is tried again after the dive.
     */
    public synchronized void call(String host, int callPort, String vehicleName, Duration diveTime,
                                  Duration surfaceTime) {
        SurfaceDialog dialog = new SurfaceDialog(vehicleName);
        thread = new Thread(() -> callLoop(host, callPort, dialog, diveTime, surfaceTime), "glider-simulator-call");
        thread.setDaemon(true);
        thread.start();
        log.info("glider simulator {} calls {}:{} every {} s for {} s, files in {}", vehicleName, host, callPort,
                diveTime.toSeconds(), surfaceTime.toSeconds(), dir);
    }

    private void callLoop(String host, int callPort, SurfaceDialog dialog, Duration diveTime, Duration surfaceTime) {
        try {
            while (running) {
                Duration away = diveTime;
                boolean dives = true;
                Link link = null;
                try (Socket socket = new Socket()) {
                    socket.connect(new InetSocketAddress(host, callPort), 10_000);
                    link = wrap(new TcpLink(socket));
                    current = link;
                    calls++;
                    ShellLink shell = new ShellLink(link);
                    if (gliderDos == null) {
                        say(shell, dialog.text(calls, Instant.now(), "SIM.MI", plan.dialogLines()) + PROMPT);
                        converse(shell, System.nanoTime() + surfaceTime.toNanos(), dialog::chatter, 0);
                        submerged = true;
                        say(shell, "\r\nHanging up: diving for " + diveTime.toSeconds() + " s\r\n");
                    } else {
                        away = surfacing(shell, dialog, diveTime);
                        dives = !(pendingEnd instanceof GliderDos.CallBack);
                    }
                    link.close();
                } catch (IOException e) {
                    log.info("call {} to {}:{} ended: {}", calls, host, callPort, e.getMessage());
                    if (link instanceof IridiumLine l && l.dropped()) {
                        away = REDIAL; // still at the surface: the glider dials again
                        dives = false;
                    }
                } finally {
                    current = null;
                    if (link instanceof IridiumLine l) {
                        l.cut(); // its threads end with the call, however it ended
                    }
                }
                submerged = dives;
                dive(away);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            stopped.countDown();
        }
    }

    /**
     * One GliderDOS surfacing: the dialog, the keys and the countdown, GliderDOS if the pilot
     * took control; says how it ends and returns how long the glider is away: {@code diveTime}
     * for a dive, a {@code callback}'s time (at the surface) for a call back.
     */
    private Duration surfacing(ShellLink shell, SurfaceDialog dialog, Duration diveTime) throws IOException {
        GliderDos g = gliderDos;
        g.surfaced();
        pendingEnd = null;
        say(shell, dialog.fullText(calls, Instant.now(), g.mission(), plan.waypointLines() + g.reportLines(), trouble));
        SurfaceCountdown.Answer a = SurfaceCountdown.run(shell, surfaceWait, surfaceWait, dir);
        if (a == SurfaceCountdown.Answer.CONTROL_C) {
            say(shell, g.prompt());
            converse(shell, System.nanoTime() + surfaceWait.toNanos(), null, surfaceWait.toNanos());
            if (pendingEnd == null && running) {
                say(shell, "\r\nNo input for " + surfaceWait.toSeconds() + " s: resuming the mission.\r\n");
            }
        }
        if (pendingEnd instanceof GliderDos.CallBack cb) {
            return cb.after();
        }
        submerged = true;
        say(shell, "Hanging up: diving for " + diveTime.toSeconds() + " s\r\n");
        return diveTime;
    }

    /** How many calls it has made ({@link #call}). */
    public int calls() {
        return calls;
    }

    public boolean submerged() {
        return submerged;
    }

    /** Runs one conversation; returns how long it is then away (GO, a resumed mission, a callback), or null. */
    private Duration session(Link link) throws IOException {
        ShellLink shell = new ShellLink(link);
        if (gliderDos != null) {
            calls++;
            return surfacing(shell, new SurfaceDialog(name), submerge);
        }
        say(shell, "\r\nPicoDOS (RIPV glider simulator)\r\n" + PROMPT);
        return converse(shell, 0, null, 0) ? submerge : null;
    }

    /**
     * Answers commands until GO (true), or, when {@code until} is not 0, until that time has come
     * between two commands (true: the surface time is over). {@code chatter} is printed when the
     * line has been idle a while, as a vehicle's own output. With {@code renew} (nanoseconds), each
     * command moves {@code until} to that long after it: a time without input, as GliderDOS has.
     */
    private boolean converse(ShellLink shell, long until, LongFunction<String> chatter, long renew)
            throws IOException {
        StringBuilder line = new StringBuilder();
        byte[] buf = new byte[1024];
        boolean lastWasCr = false;
        long lastChatter = System.nanoTime();
        while (running) {
            if (until != 0 && line.isEmpty() && System.nanoTime() - until > 0) {
                return true;
            }
            int n = shell.read(buf, 0, buf.length, 1000);
            if (n == 0 && chatter != null && line.isEmpty() && System.nanoTime() - lastChatter > 10_000_000_000L) {
                lastChatter = System.nanoTime();
                say(shell, chatter.apply(until == 0 ? 0 : (until - lastChatter) / 1_000_000_000L) + "\r\n" + prompt());
            }
            for (int i = 0; i < n; i++) {
                int c = buf[i] & 0xFF;
                if (c == '\n' && lastWasCr) {
                    lastWasCr = false;
                    continue;
                }
                lastWasCr = c == '\r';
                if (c == '\r' || c == '\n') {
                    say(shell, "\r\n");
                    shell.unread(buf, i + 1, n - i - 1);
                    String command = line.toString().trim();
                    line.setLength(0);
                    if (execute(shell, command)) {
                        return true;
                    }
                    if (renew > 0) {
                        until = System.nanoTime() + renew;
                    }
                    say(shell, prompt());
                    break;
                } else if (c == 8 || c == 0x7F) {
                    if (!line.isEmpty()) {
                        line.setLength(line.length() - 1);
                        say(shell, "\b \b");
                    }
                } else if (c == SurfaceCountdown.CTRL_C && gliderDos != null) {
                    line.setLength(0); // GliderDOS drops the line typed so far and prompts again
                    say(shell, "^C\r\n" + prompt());
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
            say(shell, plan.put(words)); // a glider's put, at the simple shell too (docs/plans.md)
            return false;
        }
        GliderDos.Answer answer = g == null ? null : g.execute(verb, words);
        if (answer != null) {
            say(shell, answer.text());
            pendingEnd = answer.end();
            return answer.end() != null;
        }
        switch (verb) {
            case "DIR" -> say(shell, dir());
            case "TYPE" -> {
                Path file = file(shell, words);
                if (file != null) {
                    String text = new String(Files.readAllBytes(file), StandardCharsets.ISO_8859_1);
                    say(shell, text.replace("\r\n", "\n").replace("\n", "\r\n") + (text.endsWith("\n") ? "" : "\r\n"));
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
            case "ZR" -> say(shell, "\r\n" + Lrzsz.receive(shell, dir) + "\r\n");
            case "GO" -> {
                submerged = true; // from now on, before the link drops
                say(shell, "Mission started; submerging for " + submerge.toSeconds() + " s\r\n");
                pendingEnd = new GliderDos.Resume("GO");
                return true;
            }
            case "MONITOR" -> monitor(shell, words);
            case "HELP", "?" -> say(shell, "dir, type NAME, del NAME, ys NAME..., yr, zs NAME..., zr, monitor [SECONDS], go\r\n");
            default -> say(shell, "Bad command or file name\r\n");
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
                say(shell, "usage: monitor [SECONDS]\r\n");
                return;
            }
        }
        long end = System.nanoTime() + seconds * 1_000_000_000L;
        byte[] keys = new byte[64];
        for (int i = 0; running && System.nanoTime() - end < 0; i++) {
            int n = shell.read(keys, 0, keys.length, 250);
            for (int k = 0; k < n; k++) {
                if (keys[k] == 3) {
                    say(shell, "^C\r\n");
                    return;
                }
            }
            say(shell, String.format(Locale.ROOT, "m_depth %.2f m\r\n", 5 + 3 * Math.sin(i / 8.0)));
        }
    }

    private Path file(ShellLink shell, String[] words) throws IOException {
        if (words.length != 2) {
            say(shell, "Required parameter missing\r\n");
            return null;
        }
        Path file = resolve(words[1]);
        if (file == null) {
            say(shell, "File not found - " + words[1] + "\r\n");
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

    private void send(ShellLink shell, String[] words) throws IOException {
        if (words.length < 2) {
            say(shell, "usage: ys NAME...\r\n");
            return;
        }
        List<SendFile> files = new ArrayList<>();
        for (int i = 1; i < words.length; i++) {
            Path p = resolve(words[i]);
            if (p == null) {
                say(shell, "File not found - " + words[i] + "\r\n");
                return;
            }
            files.add(SendFile.of(p));
        }
        try {
            new YmodemSender(shell, ymodem, null).sendBatch(files);
            say(shell, "\r\n" + files.size() + " file(s) sent\r\n");
        } catch (YmodemException e) {
            say(shell, "\r\nYMODEM send failed: " + e.getMessage() + "\r\n");
        }
    }

    /** {@code zs NAME...}: lrzsz's sz sends the files (names matched without regard to case). */
    private void zsend(ShellLink shell, String[] words) throws IOException {
        if (words.length < 2) {
            say(shell, "usage: zs NAME...\r\n");
            return;
        }
        List<String> names = new ArrayList<>();
        for (int i = 1; i < words.length; i++) {
            Path p = resolve(words[i]);
            if (p == null) {
                say(shell, "File not found - " + words[i] + "\r\n");
                return;
            }
            names.add(p.getFileName().toString());
        }
        say(shell, "\r\n" + Lrzsz.send(shell, dir, names) + "\r\n");
    }

    private void receive(ShellLink shell) throws IOException {
        try {
            List<FileHeader> got = new YmodemReceiver(shell, ymodem, null).receiveBatch(new DirectorySink(dir));
            say(shell, "\r\n" + got.size() + " file(s) received\r\n");
        } catch (YmodemException e) {
            say(shell, "\r\nYMODEM receive failed: " + e.getMessage() + "\r\n");
        }
    }

    static void say(ShellLink shell, String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.ISO_8859_1);
        shell.write(bytes, 0, bytes.length);
        shell.flush();
    }

    /** The TCP port it listens on (0 when attached to a tty). */
    public int port() {
        return port;
    }

    /** Blocks until the simulator stops. */
    public void await() throws InterruptedException {
        stopped.await();
    }

    @Override
    public void close() {
        running = false;
        stopped.countDown();
        ServerSocket s = serverSocket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        Link l = current;
        if (l instanceof IridiumLine il) {
            il.cut(); // stopping: no waiting for the line to drain
        } else if (l != null) {
            l.close();
        }
    }
}
