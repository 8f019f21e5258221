package org.ripv.server.plans;

import java.io.IOException;

import org.ripv.messages.ConsoleEntry;
import org.ripv.server.files.FileStore;
import org.ripv.server.permit.PermitFile;

/** The server as plans see it: the stores, the permit file, the console, and the workflow queue. */
public interface PlanHost {
    FileStore files();

    PermitFile permits();

    /** A console entry the server originates (events for watchers, the transcript and notifications). */
    void publish(ConsoleEntry entry);

    /** Queues a workflow written for {@code user}; returns its id ({@code Workflows.queueGenerated}). */
    long queueWorkflow(String mailbox, String user, String label, String source) throws IOException;
}
