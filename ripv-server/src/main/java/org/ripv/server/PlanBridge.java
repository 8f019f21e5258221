package org.ripv.server;

import java.io.IOException;

import org.ripv.messages.ConsoleEntry;
import org.ripv.server.files.FileStore;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.plans.PlanHost;

/** The server as plans see it (org.ripv.server.plans.PlanHost). */
final class PlanBridge implements PlanHost {
    private final RIPVServer server;

    PlanBridge(RIPVServer server) {
        this.server = server;
    }

    @Override
    public FileStore files() {
        return server.files();
    }

    @Override
    public PermitFile permits() {
        return server.permits();
    }

    @Override
    public void publish(ConsoleEntry entry) {
        server.publishServerEntry(entry);
    }

    @Override
    public long queueWorkflow(String mailbox, String user, String label, String source) throws IOException {
        return server.workflows().queueGenerated(mailbox, user, label, source);
    }
}
