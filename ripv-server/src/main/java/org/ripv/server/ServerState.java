package org.ripv.server;

import java.io.IOException;
import org.ripv.server.security.Audit;
import org.ripv.server.store.AuditTrail;
import org.ripv.server.store.StateStore;
import org.ripv.server.store.StateStores;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's state store, opened as its configuration says (embedded or PostgreSQL), with the
 * audit trail feeding it; RIPVServer opens it first and closes it last.
 */
final class ServerState implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ServerState.class);

    private final StateStore store;
    private final AuditTrail audit;
    private final AutoCloseable trail;

    private ServerState(StateStore store) {
        this.store = store;
        this.audit = new AuditTrail(store);
        this.trail = Audit.addTrail(audit::record);
    }

    static ServerState open(ServerConfig config, SessionOptions options) throws IOException {
        StateStore store = StateStores.open(config.stateStore(), config.dataDir(), options.transcriptFileBytes());
        log.info("server state (transcripts, workflow queues and receipts, subscriptions, audit trail): {}", store.describe());
        return new ServerState(store);
    }

    StateStore store() {
        return store;
    }

    AuditTrail audit() {
        return audit;
    }

    /** After the transcripts, workflows and notifier have stored what they hold. */
    @Override
    public void close() {
        try {
            trail.close();
        } catch (Exception e) {
            log.debug("audit trail: {}", e.toString());
        }
        audit.close();
        store.close();
    }
}
