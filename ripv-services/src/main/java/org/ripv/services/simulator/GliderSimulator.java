package org.ripv.services.simulator;

import java.io.EOFException;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.ripv.services.serial.Link;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialLink;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
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
 * with a {@link SurfaceDialog} on each call. This class is how the vehicle is reached and when
 * it is away; what it answers once reached is its {@link GliderShell}, whose files live in one
 * directory. {@code zs} and {@code zr} run lrzsz ({@link Lrzsz}). {@link #speakGliderDos} makes each call a Slocum's
 * surfacing ({@link SurfaceCountdown}, {@link GliderDos}); {@link #overLine} makes TCP calls
 * Iridium-like ({@link IridiumLine}).
 */
public final class GliderSimulator implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(GliderSimulator.class);
    static final String PROMPT = GliderShell.PROMPT;

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
    private volatile SurfaceTrouble trouble = SurfaceTrouble.NONE;
    /** What its plan (goto_l10.ma, put values) makes its dialog print. */
    private final PlanState plan;
    private volatile Duration surfaceWait = Duration.ofSeconds(60);
    private volatile IridiumLine.Settings line = IridiumLine.Settings.NONE;
    private volatile String name = "sim01";
    private final GliderShell vehicleShell;
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
        this.vehicleShell = new GliderShell(this.dir, ymodem, plan, submerge, () -> running, () -> submerged = true);
        GliderShell.seed(this.dir);
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
        vehicleShell.speakGliderDos(new GliderDos(dir, minute));
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
                    if (vehicleShell.gliderDos() == null) {
                        shell.say(dialog.text(calls, Instant.now(), "SIM.MI", plan.dialogLines()) + PROMPT);
                        vehicleShell.converse(shell, System.nanoTime() + surfaceTime.toNanos(), dialog::chatter, 0);
                        submerged = true;
                        shell.say("\r\nHanging up: diving for " + diveTime.toSeconds() + " s\r\n");
                    } else {
                        away = surfacing(shell, dialog, diveTime);
                        dives = !(vehicleShell.end() instanceof GliderDos.CallBack);
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
        GliderDos g = vehicleShell.gliderDos();
        g.surfaced();
        vehicleShell.clearEnd();
        shell.say(dialog.fullText(calls, Instant.now(), g.mission(), plan.waypointLines() + g.reportLines(), trouble));
        SurfaceCountdown.Answer a = SurfaceCountdown.run(shell, surfaceWait, surfaceWait, dir);
        if (a == SurfaceCountdown.Answer.CONTROL_C) {
            shell.say(g.prompt());
            vehicleShell.converse(shell, System.nanoTime() + surfaceWait.toNanos(), null, surfaceWait.toNanos());
            if (vehicleShell.end() == null && running) {
                shell.say("\r\nNo input for " + surfaceWait.toSeconds() + " s: resuming the mission.\r\n");
            }
        }
        if (vehicleShell.end() instanceof GliderDos.CallBack cb) {
            return cb.after();
        }
        submerged = true;
        shell.say("Hanging up: diving for " + diveTime.toSeconds() + " s\r\n");
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
        if (vehicleShell.gliderDos() != null) {
            calls++;
            return surfacing(shell, new SurfaceDialog(name), submerge);
        }
        shell.say("\r\nPicoDOS (RIPV glider simulator)\r\n" + PROMPT);
        return vehicleShell.converse(shell, 0, null, 0) ? submerge : null;
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
