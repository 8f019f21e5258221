package org.ripv.services.database;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import org.ripv.dac.delivery.Deliveries;
import org.ripv.messages.Ids;
import org.ripv.naming.Handles;
import org.ripv.service.RIPVService;
import org.ripv.services.ingest.IngestLimits;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The DatabaseServer (thesis 4.1.4.2, SID {@value org.ripv.messages.Ids#SID_DATABASE}): JDBC to
 * any database, one MailBox per database connection. The command is SQL; a query answers with a
 * table, an update with its count, bad SQL with the database's message and SQLState (see
 * {@link DatabaseHandler}). The client shows its tables in the DatabasePanel ("DAB").
 *
 * <pre>{@code
 * // the embedded default: Derby in DATA/vehicledb, created and seeded on first start
 * DatabaseTarget db = EmbeddedDatabase.prepare(Path.of("data"), Handles.platformDefault());
 * DatabaseServer server = new DatabaseServer("deslab.mit.edu", List.of(db), QueryLimits.defaults());
 * ServiceConnector.connect(server, options);   // or server.start() and server.accept(...) in-process
 * }</pre>
 *
 * <p>MailBox handles follow Appendix A: the one database of a default setup is the platform's
 * static handle ({@code TTY1}, {@code COM1} on Windows); further databases are {@code TTY2},
 * {@code TTY3}, ... in the order given ({@link #handles}).
 */
public final class DatabaseServer extends RIPVService {
    private static final Logger log = LoggerFactory.getLogger(DatabaseServer.class);

    /** The service name of Appendix A. */
    public static final String NAME = "DatabaseServer";

    private final List<DatabaseTarget> targets;
    private final QueryLimits limits;
    private final List<DatabaseHandler> handlers = new ArrayList<>();
    private volatile IngestLimits ingestLimits = IngestLimits.defaults();
    private volatile Deliveries deliveries = Deliveries.NONE;

    public DatabaseServer(String host, List<DatabaseTarget> targets, QueryLimits limits) {
        super(NAME, Ids.SID_DATABASE, host);
        if (targets.isEmpty()) {
            throw new IllegalArgumentException("a DatabaseServer needs at least one database");
        }
        Set<String> seen = new HashSet<>();
        for (DatabaseTarget t : targets) {
            if (!seen.add(t.handle())) {
                throw new IllegalArgumentException("two databases with MailBox handle " + t.handle());
            }
        }
        this.targets = List.copyOf(targets);
        this.limits = Objects.requireNonNull(limits, "limits");
    }

    /** How much one ingested file may hold (issue 33 item 8); set before the service starts. */
    public DatabaseServer withIngestLimits(IngestLimits limits) {
        this.ingestLimits = Objects.requireNonNull(limits, "limits");
        return this;
    }

    /** The DAC deployments that get every Slocum file ingested here (issue 37, {@code --dac}); set before the service starts. */
    public DatabaseServer withDeliveries(Deliveries deliveries) {
        this.deliveries = Objects.requireNonNull(deliveries, "deliveries");
        return this;
    }

    /** The MailBox handles for {@code n} databases: TTY1, TTY2, ... (COM1, COM2, ... on Windows). */
    public static List<String> handles(int n) {
        String first = Handles.platformDefault();
        String stem = first.replaceAll("\\d+$", "");
        List<String> out = new ArrayList<>(n);
        for (int i = 1; i <= n; i++) {
            out.add(stem + i);
        }
        return out;
    }

    @Override
    protected void open() {
        for (DatabaseTarget t : targets) {
            DatabaseHandler h = new DatabaseHandler(t, limits,
                    IngestNotices.publishing(name().mailbox(t.handle()).toString(), this::publish)).withIngestLimits(ingestLimits)
                    .withDeliveries(deliveries);
            try {
                h.connect();
            } catch (SQLException e) {
                // Serve anyway: ?status shows why, and each command tries to connect again.
                log.warn("{}: cannot connect to {} yet: {}", name(), t.safeUrl(), DatabaseHandler.describe(e));
            }
            handlers.add(h);
            openMailBox(t.handle(), h);
        }
    }

    @Override
    protected void close() {
        for (DatabaseHandler h : handlers) {
            h.close();
        }
        handlers.clear();
        deliveries.close();
    }

    @Override
    protected String description() {
        StringBuilder b = new StringBuilder("SQL to ");
        for (int i = 0; i < targets.size(); i++) {
            b.append(i == 0 ? "" : ", ").append(targets.get(i).handle()).append(": ").append(targets.get(i).safeUrl());
        }
        return b.toString();
    }

    /** {@code ingest NAME...}: the server attaches the named download-directory files. */
    @Override
    protected List<String> downloadPrefixes() {
        return List.of(IngestCommand.WORD);
    }

    @Override
    protected String panel() {
        return "DAB";
    }

    /** The databases served, in MailBox order. */
    public List<DatabaseTarget> targets() {
        return targets;
    }

    public QueryLimits limits() {
        return limits;
    }
}
