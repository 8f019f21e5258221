package org.ripv.server.dataloop;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.ripv.messages.Attachment;
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
import org.ripv.slocum.SlocumFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Automatic ingest: when a SerialPortServer reply puts Slocum DBA files (recognised by their first
 * line, not their names) in the download directory, the server sends {@code ingest NAME...} to a
 * DatabaseServer MailBox on the fetching user's behalf, tells that user (PROGRESS), and adds the
 * result to the download's own OK reply, which stays OK whatever the ingest made of the files
 * ({@link IngestVerdict}). On by default, per vehicle ({@link IngestSettings}). The files go to the
 * DatabaseServer as the bytes the SerialPortServer's reply brought: the server stores its copy for
 * the user and never reads it back to ingest it; it still decides whether the user may have each
 * file ({@link ServiceCalls#whyNotDownload}) and records the ingest in the reply.
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

    public DataLoop(ServiceCalls calls, Path settingsFile) {
        this.calls = calls;
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
        // The bytes the service just sent go on as they are: the stored copy is the user's, never read back for this.
        calls.call(database, "ingest " + String.join(" ", names), user, List.of(INGEST_ROLE), Attachment.bundle(bytes), f -> { })
                .whenComplete((f, e) -> {
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
