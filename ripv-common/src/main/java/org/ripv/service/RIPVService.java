package org.ripv.service;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.handout.HandoutCollector;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.Handles;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.ServiceName;
import org.ripv.post.MailBox;
import org.ripv.post.PostOffice;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The base class of every RIPV service (thesis 4.1.4, figure 5.4). A service owns resources —
 * serial ports, database connections, plot workers — and opens one MailBox per resource, each
 * with a {@link CommandHandler} that runs that MailBox's commands one at a time, highest
 * priority first. The server forwards operators' commands here and relays the replies back.
 *
 * <p>A minimal service:
 * <pre>{@code
 * public final class ClockService extends RIPVService {
 *     public ClockService() {
 *         super("ClockService", "100100");
 *     }
 *
 *     protected void open() {
 *         openMailBox(Handles.platformDefault(), request -> switch (request.command()) {
 *             case "time" -> Reply.ok(Instant.now().toString());
 *             default -> Reply.error(ErrorCode.UNKNOWN_COMMAND, "unknown command '" + request.command() + "'");
 *         });
 *     }
 * }
 * // Run it in-process, or register it with a server:
 * ClockService clock = new ClockService();
 * ServiceConnector.connect(clock, ServiceOptions.of("server.example.org", 1099, secret));
 * }</pre>
 *
 * <p>Everything {@link #open} registers is callable locally ({@link #accept}) and over RMI (via
 * {@link ServiceConnector}), so the same tests can exercise both.
 */
public abstract class RIPVService {
    private static final Logger log = LoggerFactory.getLogger(RIPVService.class);

    private final ServiceName name;
    private final String sid;
    /** When this instance was made: a call the server saw before then is not this instance's (ServiceDescriptor.started). */
    private final long created = System.currentTimeMillis();
    private final PostOffice<IncomingServiceMessage, OutgoingServiceMessage> postOffice = new PostOffice<>(100_000);
    private final Map<String, CommandHandler> handlers = new ConcurrentHashMap<>();
    private final Map<String, ServiceTaskManager> managers = new ConcurrentHashMap<>();
    private volatile ReplySink sink = reply -> log.warn("not connected to a server: dropped {}", reply);
    private volatile boolean started;
    private volatile ConsolePublisher console;
    private final ServiceHandouts handouts;

    /**
     * @param serviceName the service's name (Appendix A, II), e.g. {@code "SerialPortServer"}
     * @param sid         its six-digit service id (Appendix B); pick one no other service uses
     */
    protected RIPVService(String serviceName, String sid) {
        this(serviceName, sid, Handles.localHost());
    }

    /** As {@link #RIPVService(String, String)}, registering under an explicit host name. */
    protected RIPVService(String serviceName, String sid, String host) {
        this.name = new ServiceName(serviceName, host);
        this.sid = Ids.require(sid);
        this.handouts = new ServiceHandouts(name.toString(), this::handsOutFiles);
    }

    /** Opens the service's resources and MailBoxes with {@link #openMailBox}. */
    protected abstract void open() throws Exception;

    /** Releases the service's resources. MailBoxes are closed already. */
    protected void close() {
    }

    /** One line the operator sees in the service tree. */
    protected String description() {
        return "";
    }

    /** The client's fourth panel for this service: "DAB", "DAV", or "" (COM spans both rows). */
    protected String panel() {
        return "";
    }

    /** Command prefixes whose first argument names an uploaded file for the server to attach. */
    protected List<String> attachPrefixes() {
        return List.of();
    }

    public final ServiceName name() {
        return name;
    }

    /**
     * Command words whose arguments all name files in the server's download directory, which
     * the server attaches as one {@link org.ripv.messages.Attachment#bundle bundle}
     * ({@code ingest NAME...} of the DatabaseServer).
     */
    protected List<String> downloadPrefixes() {
        return List.of();
    }

    public final String sid() {
        return sid;
    }

    public final ServiceDescriptor descriptor() {
        return new ServiceDescriptor(name.toString(), sid, description(), panel(), attachPrefixes(), downloadPrefixes())
                .withStarted(created);
    }

    /** Opens a MailBox for a resource; its commands go to {@code handler}, one at a time. */
    protected final MailboxAddress openMailBox(String handle, CommandHandler handler) {
        MailboxAddress address = name.mailbox(handle);
        Objects.requireNonNull(handler, "handler");
        handlers.put(address.toString(), handler);
        ServiceTaskManager manager = new ServiceTaskManager(this, handler);
        try {
            postOffice.open(address.toString(), manager);
        } catch (RuntimeException e) {
            handlers.remove(address.toString());
            throw e;
        }
        managers.put(address.toString(), manager);
        log.info("opened MailBox {}", address);
        return address;
    }

    /** Closes a MailBox; requests still waiting in it are answered with an error. */
    protected final void closeMailBox(String handle) {
        String address = name.mailbox(handle).toString();
        for (IncomingServiceMessage left : postOffice.close(address)) {
            replyNow(left, ErrorCode.NOT_AVAILABLE, "MailBox " + address + " was closed before the command ran");
        }
        handlers.remove(address);
        managers.remove(address);
    }

    /** Opens the service. Idempotent. */
    public final synchronized void start() throws Exception {
        if (!started) {
            open();
            started = true;
        }
    }

    /** Closes every MailBox and the service's resources. */
    public final synchronized void stop() {
        if (started) {
            started = false;
            for (MailBox<IncomingServiceMessage, OutgoingServiceMessage> box : postOffice.mailboxes()) {
                closeMailBox(box.address().substring(name.toString().length()));
            }
            close();
            if (console != null) {
                console.stop();
                console = null;
            }
        }
    }

    /**
     * Publishes what a resource did on its own — a vehicle's unsolicited line, a command sent,
     * an event, a transfer's progress — to everyone watching its MailBox (the live console). Never
     * blocks: entries travel on a thread of their own, and are skipped (and counted) if the
     * server cannot keep up.
     */
    protected final void publish(ConsoleEntry entry) {
        ConsolePublisher p = console;
        if (p == null) {
            synchronized (this) {
                if (console == null) {
                    console = new ConsolePublisher(name.toString(), 10_000, this::sink);
                }
                p = console;
            }
        }
        p.publish(entry);
    }

    /**
     * Whether this service keeps the files its replies send for a while, so that another service
     * (a DatabaseServer's {@code ingest}) can read them here rather than through the server
     * ({@link org.ripv.handout}). Off by default; a service that fetches files turns it on.
     */
    protected boolean handsOutFiles() {
        return false;
    }

    /** How this service finds the others it reads handed-out files from (set by the connector). */
    final void peersVia(HandoutCollector.Peers peers) {
        handouts.peersVia(peers);
    }

    final ServiceHandouts handouts() {
        return handouts;
    }

    /** The next chunk of a file this service holds, for another service with the server's ticket. */
    final byte[] handout(String ticket, long offset, int max, String token) {
        return handouts.read(ticket, offset, max, token);
    }

    /** Sets where replies go (the server link, or a test's collector). */
    public final void replyTo(ReplySink newSink) {
        this.sink = Objects.requireNonNull(newSink, "sink");
    }

    final ReplySink sink() {
        return sink;
    }

    /**
     * Accepts a request from the server: files it in its MailBox, or answers at once with an
     * error when the MailBox does not exist or is full.
     */
    public final void accept(IncomingServiceMessage request) {
        switch (postOffice.scan(request)) {
            case DELIVERED -> { }
            case UNKNOWN_MAILBOX -> replyNow(request, ErrorCode.UNKNOWN_MAILBOX,
                    "no MailBox '" + request.header().mailboxAddress() + "' at " + name + "; ask ?mailboxes for the list");
            case FULL -> replyNow(request, ErrorCode.NOT_AVAILABLE,
                    "MailBox " + request.header().mailboxAddress() + " has too many commands waiting; try later");
        }
    }

    private void replyNow(IncomingServiceMessage request, ErrorCode code, String text) {
        try {
            sink.reply(request.reply(Footer.error(sid, code, text).via(name.toString())));
        } catch (Exception e) {
            log.warn("could not send error reply for #{}: {}", request.header().messageId(), e.toString());
        }
    }

    /**
     * Withdraws a request still waiting in a MailBox (the server gave up on it), so that a
     * command the operator was told failed does not run later.
     */
    public final boolean withdraw(String mailbox, String clientId, long messageId) {
        return postOffice.mailbox(mailbox).map(box -> box.remove(m -> m.header().messageId() == messageId
                && m.header().origin().clientId().equals(clientId))).orElse(false);
    }

    /**
     * Asks the handler of a MailBox to stop a request ({@code ?cancel}). A request that has not
     * started (on its way from the server, or waiting in the MailBox) never runs: it is answered
     * CANCELLED when it comes up, since an operator's cancel can overtake the request it names.
     *
     * @return true when that request is running there and the handler accepted the cancel
     *         ({@link CommandHandler#cancel}), or when it has not started; its final reply then
     *         says CANCELLED. False for a running request whose handler cannot stop it, one that
     *         has already ended, or an unknown MailBox
     */
    public final boolean cancel(String mailbox, String clientId, long messageId) {
        ServiceTaskManager m = managers.get(mailbox);
        return m != null && m.cancel(clientId, messageId);
    }

    /**
     * The reader took a page of the table the request is sending ({@code Request.page}): the
     * server calls this once the page went out to the client's socket.
     *
     * @return true when that request is running there
     */
    public final boolean pageTaken(String mailbox, String clientId, long messageId) {
        ServiceTaskManager m = managers.get(mailbox);
        return m != null && m.pageTaken(clientId, messageId);
    }

    /** The MailBoxes and their availability. */
    public final List<MailboxStatus> mailboxes() {
        List<MailboxStatus> out = new ArrayList<>();
        for (MailBox<IncomingServiceMessage, OutgoingServiceMessage> box : postOffice.mailboxes()) {
            CommandHandler h = handlers.get(box.address());
            Availability a;
            try {
                a = h == null ? Availability.notAvailable("closed") : h.availability();
            } catch (RuntimeException e) {
                a = Availability.notAvailable(e.toString());
            }
            out.add(new MailboxStatus(box.address(), a.available(), a.detail(), box.key().isHeld(), "", null, a.running()));
        }
        return out;
    }

    @Override
    public String toString() {
        return name + " (SID " + sid + ")";
    }
}
