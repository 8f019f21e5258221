package org.ripv.server.plans;

import java.io.IOException;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.ripv.server.files.FileStore;
import org.ripv.server.permit.PermitFile;

/** The server as plans see it ({@link PlanHost}), given the parts it stands for. */
public final class PlanBridge implements PlanHost {
    /** Queues a workflow written for a user; returns its id ({@code Workflows.queueGenerated}). */
    @FunctionalInterface
    public interface WorkflowQueue {
        long queue(String mailbox, String user, String label, String source) throws IOException;
    }

    private final FileStore files;
    private final Supplier<PermitFile> permits;
    private final Consumer<ConsoleEntry> publish;
    private final WorkflowQueue workflows;

    /** @param publish where the server's own console entries go */
    public PlanBridge(FileStore files, Supplier<PermitFile> permits, Consumer<ConsoleEntry> publish, WorkflowQueue workflows) {
        this.files = files;
        this.permits = permits;
        this.publish = publish;
        this.workflows = workflows;
    }

    @Override
    public FileStore files() {
        return files;
    }

    @Override
    public PermitFile permits() {
        return permits.get();
    }

    @Override
    public void publish(ConsoleEntry entry) {
        publish.accept(entry);
    }

    @Override
    public long queueWorkflow(String mailbox, String user, String label, String source) throws IOException {
        return workflows.queue(mailbox, user, label, source);
    }
}
