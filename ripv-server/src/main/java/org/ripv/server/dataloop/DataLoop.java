package org.ripv.server.dataloop;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.ripv.handout.HandoutCollector;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Result;
import org.ripv.messages.Status;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.Handles;
import org.ripv.server.handout.HandoutTickets;
import org.ripv.slocum.SlocumFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Automatic ingest: when a SerialPortServer reply puts Slocum DBA files (recognised by their first
 * line, not their names) in the download directory, the server sends {@code ingest NAME...} to a
 * DatabaseServer MailBox on the fetching user's behalf, tells that user (PROGRESS), and adds the
 * result to the download's own OK reply, which stays OK whatever the ingest made of the files
 * ({@link IngestVerdict}). On by default, per vehicle ({@link IngestSettings}). The server decides
 * whether the user may have each file ({@link ServiceCalls#whyNotDownload}), stores its copy for the
 * user and records the ingest in the reply; the bytes go from the SerialPortServer to the
 * DatabaseServer without the server: the {@code ingest} carries one-use tickets
 * ({@link HandoutTickets}) by which the DatabaseServer reads them where they were fetched. When the
 * two cannot reach each other (outbound-only, a firewall, the file let go), the server relays the
 * bytes its reply brought, as it did before, and logs why; it never reads its stored copy back.
 */
public final class DataLoop {
    private static final Logger log = LoggerFactory.getLogger(DataLoop.class);

    /**
     * The role the server's own ingest runs with: the DatabaseServer lets {@code db-writer} write
     * (the fetching user may be an observer; the ingest is the server's act, not the user's SQL).
     */
    static final String INGEST_ROLE = "db-writer";

    private final ServiceCalls calls;
    private final IngestSettings settings;
    private final PlotRequests plots;
    private final HandoutTickets handouts;
    private final AtomicLong relayed = new AtomicLong();

    /** A data loop that relays fetched files to the DatabaseServer through the server. */
    public DataLoop(ServiceCalls calls, Path settingsFile) {
        this(calls, null, settingsFile);
    }

    /**
     * @param handouts signs the tickets by which a DatabaseServer reads fetched files from the
     *                 service that fetched them; null: relay them through the server
     */
    public DataLoop(ServiceCalls calls, HandoutTickets handouts, Path settingsFile) {
        this.calls = calls;
        this.handouts = handouts;
        this.settings = new IngestSettings(settingsFile);
        this.plots = new PlotRequests(calls, this::database);
    }

    /**
     * Takes over a plot from data (a {@link PlotKind}: {@code vis:sql}, {@code vis:track},
     * {@code vis:depth}, {@code vis:profile}) sent to a DataVisServer MailBox; false for anything else.
     *
     * @param sid the addressed service's SID
     */
    public boolean plot(IncomingServerMessage request, String sid, String mailbox, Consumer<OutgoingServerMessage> send) {
        if (!sid.equals(Ids.SID_DATAVIS) || PlotKind.of(request.header().body()).isEmpty()) {
            return false;
        }
        return plots.handle(request, mailbox, send);
    }

    /**
     * The error for a command whose file is not in the upload directory: for {@code vis:WORD} to a
     * DataVisServer (not {@code vis:file}, whose file is a download), the plot commands are listed,
     * since a mistyped one is the likelier mistake; otherwise {@code noFile} as it is.
     */
    public static String noSuchFile(String sid, String body, String noFile) {
        String word = PlotKind.visWord(body);
        if (!sid.equals(Ids.SID_DATAVIS) || word == null) {
            return noFile;
        }
        return word.isEmpty() || word.equalsIgnoreCase("file") ? noFile : PlotRequests.notAPlot(word, noFile);
    }

    /**
     * Looks at a reply whose files the server has just stored.
     *
     * @param reply the reply as it would go to the client
     * @param sent  the result the service sent (with the files' bytes)
     * @param send  how to send replies to the client
     * @return true when this took the reply over (it will send it, after the ingest)
     */
    public boolean downloaded(OutgoingServerMessage reply, Result sent, Consumer<OutgoingServerMessage> send) {
        if (reply.status() != Status.OK || !reply.footer().serviceId().equals(Ids.SID_SERIAL)) {
            return false;
        }
        List<FileData> files = sent instanceof FileData d ? List.of(d) : sent instanceof FileBundle b ? b.files() : List.of();
        // the names the files were stored under (FOLDER/NAME), in the same order
        List<FileListing.Entry> stored = reply.footer().result() instanceof FileListing l ? l.files() : List.of();
        if (stored.size() != files.size()) {
            return false;
        }
        String handle = handle(reply.header().mailboxAddress());
        List<String> names = new ArrayList<>();
        List<Attachment> bytes = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            FileData f = files.get(i);
            if ((isDba(f.data()) || isSlocumBinary(f.name(), f.data())) && settings.enabled(vehicle(f.data()), handle)) {
                names.add(stored.get(i).name());
                bytes.add(new Attachment(stored.get(i).name(), f.data()));
            }
        }
        if (names.isEmpty()) {
            return false;
        }
        String database = database();
        String user = reply.header().origin().user();
        int fetched = files.size();
        if (database == null) {
            log.warn("not ingesting {} for {}: no DatabaseServer is registered", names, user);
            send.accept(IngestVerdict.notIngested(reply, fetched, "not ingested: no DatabaseServer is registered"));
            return true;
        }
        for (String name : names) {
            String why = calls.whyNotDownload(user, name); // the server decides rights, as for a client's ingest NAME
            if (why != null) {
                send.accept(IngestVerdict.notIngested(reply, fetched, "not ingested (FORBIDDEN): " + why));
                return true;
            }
        }
        String what = names.size() == 1 ? names.get(0) : names.size() + " Slocum files";
        send.accept(progress(reply, "ingesting " + what + " into " + database));
        String body = "ingest " + String.join(" ", names);
        String source = reply.header().serviceDestination();
        Optional<Attachment> tickets = handouts == null ? Optional.empty()
                : handouts.tickets(source, serviceOf(database), bytes);
        CompletableFuture<Footer> ingested;
        if (tickets.isPresent()) {
            // The DatabaseServer reads the files from the SerialPortServer; the server's copy is the user's, never sent on.
            log.info("automatic ingest of {} for {}: {} reads the bytes from {} by ticket", names, user, database, source);
            ingested = calls.call(database, body, user, List.of(INGEST_ROLE), tickets.get(), f -> { })
                    .thenCompose(f -> handoutRefused(f) ? relay(database, body, user, names, bytes, f.replyText())
                            : CompletableFuture.completedFuture(f));
        } else {
            ingested = relay(database, body, user, names, bytes, source + " or " + database
                    + " is not reachable but through the server (not registered on RMI, or outbound-only)");
        }
        ingested.whenComplete((f, e) -> {
            OutgoingServerMessage verdict;
            if (e != null) {
                verdict = IngestVerdict.notIngested(reply, fetched, "not ingested: " + e);
            } else if (f.status() == Status.OK || f.replyText().lines().anyMatch(IngestVerdict::notIngested)) {
                // per-file lines: some files refused or stored already, each said so
                verdict = IngestVerdict.ingested(reply, fetched, names.size(), database, f.replyText());
            } else {
                verdict = IngestVerdict.notIngested(reply, fetched, "not ingested (" + f.errorCode() + "): "
                        + f.replyText());
            }
            log.info("automatic ingest of {} for {}: {}", names, user, verdict.footer().replyText().replace('\n', ' '));
            send.accept(verdict);
        });
        return true;
    }

    /**
     * The old way, kept for when the services cannot reach each other: the bytes the service just
     * sent go on as they are, attached to the ingest (the stored copy is the user's, never read back for this).
     */
    private CompletableFuture<Footer> relay(String database, String body, String user, List<String> names,
                                            List<Attachment> bytes, String why) {
        long n = bytes.stream().mapToLong(a -> a.data().length).sum();
        log.info("automatic ingest of {} for {}: relaying {} bytes to {} through the server: {}", names, user, n, database, why);
        relayed.addAndGet(n);
        return calls.call(database, body, user, List.of(INGEST_ROLE), Attachment.bundle(bytes), f -> { });
    }

    /** True when the DatabaseServer could not read the files by ticket (and will get them relayed). */
    private static boolean handoutRefused(Footer f) {
        return f.status() == Status.ERROR && f.errorCode() == ErrorCode.TRANSFER_FAILED
                && f.replyText().startsWith(HandoutCollector.REFUSED);
    }

    /** The bytes of fetched files this server has relayed to a DatabaseServer (none when the services hand them over). */
    public long bytesRelayed() {
        return relayed.get();
    }

    private static String serviceOf(String mailbox) {
        try {
            return MailboxAddress.parse(mailbox).service().toString();
        } catch (RuntimeException e) {
            return mailbox;
        }
    }

    private String database() {
        String configured = settings.database();
        if (configured != null) {
            return configured;
        }
        List<String> dbs = calls.services(Ids.SID_DATABASE);
        return dbs.isEmpty() ? null : dbs.get(0) + Handles.platformDefault();
    }

    private static String handle(String mailbox) {
        try {
            return MailboxAddress.parse(mailbox).handle();
        } catch (RuntimeException e) {
            return null;
        }
    }

    private static OutgoingServerMessage progress(OutgoingServerMessage reply, String text) {
        Footer f = reply.footer();
        return new OutgoingServerMessage(reply.header(), new Footer(f.serviceId(), Status.PROGRESS, null, f.route(), text, null));
    }

    /** True when a file starts with the DBA label line. */
    static boolean isDba(byte[] data) {
        return SlocumFiles.isDba(data);
    }

    /**
     * True for what the DatabaseServer's {@code ingest} decodes besides DBA text: Slocum binary
     * files (the first line is the binary label, or the name a compressed one such as
     * {@code .scd}) and sensor-list cache files ({@code CRC.cac}), docs/slocum.md.
     */
    static boolean isSlocumBinary(String name, byte[] data) {
        return SlocumFiles.isCacheName(name) || SlocumFiles.isCompressedName(SlocumFiles.baseName(name)) && data.length > 0
                || SlocumFiles.hasBinaryLabel(data);
    }

    /** The glider's name from the header's {@code filename:} tag (before the first '-'), or null. */
    static String vehicle(byte[] data) {
        return SlocumFiles.vehicle(data);
    }
}
