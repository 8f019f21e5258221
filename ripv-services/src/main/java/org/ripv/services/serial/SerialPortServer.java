package org.ripv.services.serial;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;
import org.ripv.messages.Ids;
import org.ripv.naming.Handles;
import org.ripv.service.RIPVService;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The SerialPortServer (SID 888888): a remote command line and YMODEM file transfer to the
 * vehicles on this host's serial ports and on the links named at launch.
 *
 * <p>One {@link SerialPortHandler} and one MailBox per serial port jSerialComm enumerates
 * (handle = the port's own name, {@code ttyS0}, {@code COM1}) and per configured link (handle
 * per {@link Handles#forLink}: {@code ttyV0} for {@code /tmp/ttyV0}, {@code tcp-host-port}
 * for {@code tcp://host:port}, {@code listen-PORT} for {@code listen://[ADDR:]PORT}, or the
 * link's {@code name=}). A link named explicitly wins over an enumerated port of the same handle.
 * A {@code listen://} link waits for the vehicle to call in; every link's output is published as
 * its MailBox's live console, with the call's events (see {@link VehicleConsole}).
 *
 * <pre>{@code
 * SerialPortServer serial = new SerialPortServer("shore.example.org",
 *         List.of(LinkSettings.defaults("tcp://glider-gw:4001")), null, false, workDir);
 * ServiceConnector.connect(serial, options);
 * }</pre>
 */
public final class SerialPortServer extends RIPVService {
    private static final Logger log = LoggerFactory.getLogger(SerialPortServer.class);

    private final List<VehicleLink> links;
    private final LinkSettings portDefaults;
    private final boolean enumerate;
    private final Path workDir;
    private final SerialPortHandler.LinkOpener opener;
    private final Map<String, SerialPortHandler> handlers = new LinkedHashMap<>();
    private ScheduledExecutorService scheduler;

    /**
     * @param host         the host name to register under
     * @param links        links named on the command line (device paths or tcp://host:port)
     * @param portDefaults settings for enumerated ports (their device is filled in); may be null
     *                     when {@code enumerate} is false
     * @param enumerate    whether to open a MailBox for every port jSerialComm finds
     * @param workDir      where incoming files are assembled
     */
    public SerialPortServer(String host, List<LinkSettings> links, LinkSettings portDefaults, boolean enumerate,
                            Path workDir) {
        this(host, links.stream().map(VehicleLink::of).toList(), portDefaults, enumerate, workDir, Links::open);
    }

    /** As above, with each link's call settings ({@code name=}, {@code surface=}, ...). */
    public static SerialPortServer withCalls(String host, List<VehicleLink> links, LinkSettings portDefaults,
                                             boolean enumerate, Path workDir) {
        return new SerialPortServer(host, links, portDefaults, enumerate, workDir, Links::open);
    }

    SerialPortServer(String host, List<VehicleLink> links, LinkSettings portDefaults, boolean enumerate,
                     Path workDir, SerialPortHandler.LinkOpener opener) {
        super("SerialPortServer", Ids.SID_SERIAL, host);
        this.links = List.copyOf(links);
        this.portDefaults = portDefaults;
        this.enumerate = enumerate;
        this.workDir = workDir;
        this.opener = opener;
        if (enumerate && portDefaults == null) {
            throw new IllegalArgumentException("enumerating ports needs default settings for them");
        }
    }

    @Override
    protected void open() throws IOException {
        Map<String, VehicleLink> byHandle = new LinkedHashMap<>();
        if (enumerate) {
            for (SerialPort port : SerialPort.getCommPorts()) {
                byHandle.put(port.getSystemPortName(),
                        VehicleLink.of(portDefaults.withDevice(port.getSystemPortPath())));
            }
        }
        Set<String> named = new HashSet<>();
        for (VehicleLink link : links) {
            String handle = link.handle();
            if (!named.add(handle)) {
                throw new IllegalArgumentException("two links are both named '" + handle + "'; give each its own name=");
            }
            if (byHandle.put(handle, link) != null) {
                log.info("link {} replaces the enumerated port of the same name", link.settings().device());
            }
        }
        AtomicInteger n = new AtomicInteger();
        scheduler = Executors.newScheduledThreadPool(1, r -> {
            Thread t = new Thread(r, "serial-link-monitor-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        List<String> opened = new ArrayList<>();
        for (Map.Entry<String, VehicleLink> e : byHandle.entrySet()) {
            SerialPortHandler handler = new SerialPortHandler(e.getValue(), name().mailbox(e.getKey()).toString(),
                    workDir.resolve(e.getKey()), opener, this::publish);
            handlers.put(e.getKey(), handler);
            openMailBox(e.getKey(), handler);
            try {
                handler.start(scheduler);
            } catch (IOException ex) {
                close();
                throw ex;
            }
            opened.add(e.getKey() + "=" + e.getValue().settings().device()
                    + (handler.listenPort() >= 0 ? " (port " + handler.listenPort() + ")" : ""));
        }
        if (opened.isEmpty()) {
            log.warn("no serial ports found and no --link given: the SerialPortServer has no MailBoxes");
        }
        log.info("SerialPortServer links: {}", opened);
    }

    @Override
    protected void close() {
        handlers.values().forEach(SerialPortHandler::close);
        handlers.clear();
        if (scheduler != null) {
            scheduler.shutdownNow();
        }
    }

    @Override
    protected String description() {
        return "Vehicles on serial and TCP links: plain commands (dir, type NAME, …), ymodem:get NAME…, ymodem:put NAME, zmodem:get NAME…, zmodem:put NAME, ?key KEY";
    }

    @Override
    protected String panel() {
        return "";
    }

    @Override
    protected List<String> attachPrefixes() {
        return List.of("ymodem:put ", "zmodem:put ", ToVehicleCommands.WORD + " ");
    }

    /** The files a vehicle sends go on to the DatabaseServer from here, not through the server (org.ripv.handout). */
    @Override
    protected boolean handsOutFiles() {
        return true;
    }

    /** The port a listen link's MailBox waits for calls on, or -1 for other links. */
    public int listenPort(String handle) {
        SerialPortHandler h = handlers.get(handle);
        return h == null ? -1 : h.listenPort();
    }

    /** The handles of the open MailBoxes, in order. */
    public List<String> handles() {
        return List.copyOf(handlers.keySet());
    }
}
