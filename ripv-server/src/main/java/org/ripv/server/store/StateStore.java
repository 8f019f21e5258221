package org.ripv.server.store;

import java.io.IOException;
import java.time.LocalDate;
import java.util.List;
import java.util.Optional;

/**
 * Where the server keeps what must outlive its process (users' log-in sessions aside). Each kind of
 * state is text in its owner's format; the store keeps it whole and in order. Implementations are
 * thread-safe. A method that returns has made its change durable (a file moved into place, a
 * transaction committed); one that throws has changed nothing.
 *
 * <p>Kinds, and their owners: transcripts ({@code org.ripv.server.session.Transcript}), workflow
 * queues, fetched-file lists and receipts ({@code org.ripv.server.workflow}), notification
 * subscriptions ({@code org.ripv.server.notify.Notifier}), the audit trail
 * ({@code org.ripv.server.security.Audit}, through {@link AuditTrail}).
 */
public interface StateStore extends AutoCloseable {

    /** One transcript entry: its MailBox, its time (epoch ms, UTC) and its JSON line (no line break). */
    record TranscriptLine(String mailbox, long time, String json) {}

    /**
     * What {@link #readTranscript} found.
     *
     * @param lines      JSON lines, oldest first
     * @param more       whether lines were left out by the limit
     * @param unreadable lines (or damaged files) skipped because they could not be read
     */
    record TranscriptPage(List<String> lines, boolean more, int unreadable) {}

    /** A stored document and where it came from (a file, a table row), for error messages. */
    record Stored(String where, String text) {}

    /** One audit line: when, whether it was a warning (a failure, a refusal), and {@code event key=value ...}. */
    record AuditRecord(long time, boolean warn, String line) {}

    // ---- transcripts: append-heavy; callers batch ----

    /**
     * Appends a batch of entries, each after the ones before it: with PostgreSQL in one transaction
     * (all or none); in files, a line the disk refuses is logged and skipped.
     */
    void appendTranscript(List<TranscriptLine> lines) throws IOException;

    /**
     * Why transcript lines are not being kept now (the disk is full, say), or null when they are:
     * a state people see ({@code ?history}) rather than a warning per line.
     */
    default String transcriptTrouble() {
        return null;
    }

    /**
     * A MailBox's entries at or after {@code sinceMillis}, in the order appended: the first
     * {@code limit} of them, or with {@code newest} the last {@code limit}.
     */
    TranscriptPage readTranscript(String mailbox, long sinceMillis, int limit, boolean newest) throws IOException;

    /** Deletes entries of days before {@code oldestKept} (UTC). */
    void pruneTranscripts(LocalDate oldestKept) throws IOException;

    // ---- vehicle call state ----

    /**
     * Replaces a vehicle MailBox's call state (on call, dived, lost; last contact, position,
     * calls), one JSON document whose format the server's session package owns. Kept here so a
     * standby that takes over knows where each vehicle stands.
     */
    void saveVehicleState(String mailbox, String json) throws IOException;

    Optional<String> loadVehicleState(String mailbox) throws IOException;

    // ---- call records (org.ripv.server.surfacing) ----

    /**
     * Appends a vehicle's call record (one JSON document, no line break, whose format the server's
     * surfacing package owns); the MailBox's records beyond the newest {@code keep} may be dropped.
     */
    void appendSurfacing(String mailbox, long time, String json, int keep) throws IOException;

    /** The MailBox's last {@code n} call records, oldest first. */
    List<String> lastSurfacings(String mailbox, int n) throws IOException;

    /** The MailBoxes that have call records (so the server knows their calls after a restart). */
    List<String> surfacingMailboxes() throws IOException;

    // ---- workflows ----

    /** Replaces a MailBox's workflow queue document. */
    void saveQueue(String mailbox, String document) throws IOException;

    /** Every workflow queue document (each names its MailBox inside). */
    List<Stored> loadQueues() throws IOException;

    /** Replaces a MailBox's list of files its workflows fetched. */
    void saveFetched(String mailbox, String document) throws IOException;

    Optional<String> loadFetched(String mailbox) throws IOException;

    /**
     * Stores a run's receipt under {@code name} (replacing one of that name); a new name drops
     * the MailBox's oldest receipts beyond {@code keep}. Names sort oldest first.
     */
    void saveReceipt(String mailbox, String name, String text, int keep) throws IOException;

    /** The last {@code n} receipts of a MailBox, oldest first. */
    List<String> lastReceipts(String mailbox, int n) throws IOException;

    // ---- notification subscriptions ----

    /** Replaces the subscriptions document (one JSON line per subscription). */
    void saveSubscriptions(String document) throws IOException;

    Optional<Stored> loadSubscriptions() throws IOException;

    // ---- audit trail ----

    /** Appends audit lines, all or none. */
    void appendAudit(List<AuditRecord> records) throws IOException;

    /** The last {@code last} audit lines at or after {@code sinceMillis}, oldest first. */
    List<AuditRecord> readAudit(long sinceMillis, int last) throws IOException;

    /** Where the state is, for logs and {@code ?status}: a directory, or a JDBC URL without credentials. */
    String describe();

    /** Flushes and releases files or connections. */
    @Override
    void close();
}
