package org.ripv.server.workflow;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Header;
import org.ripv.server.files.FileStore;
import org.ripv.server.permit.PermitFile;

/**
 * What the workflow runner needs of the server. {@code org.ripv.server} implements it; keeping
 * it this small is what lets the runner live outside the broker.
 */
public interface WorkflowHost {

    /** An operator lock as it stands: who holds it, from which client id, until when (epoch ms). */
    record Lock(String user, String clientId, long untilMillis) {
        boolean expired() {
            return System.currentTimeMillis() > untilMillis;
        }
    }

    /**
     * Puts a request into the server's normal request path, as if the client in its origin had
     * sent it: permits, locks and the MailBox's queue all apply. Its replies come back through
     * {@link Workflows#reply}.
     *
     * @return false when the server is overloaded and did not take it
     */
    boolean submit(Header request);

    /** The permit file in force. */
    PermitFile permits();

    /** The upload and download store. */
    FileStore files();

    /** The lock on a MailBox, or null when there is none. */
    Lock lock(String mailbox);

    /**
     * Takes or extends the lock for a workflow: succeeds when the MailBox is unlocked, its lock
     * has expired, or it is already this client id's.
     */
    boolean lockForWorkflow(String mailbox, String user, String clientId, long untilMillis);

    /** Releases the lock if this client id holds it. */
    void unlockWorkflow(String mailbox, String clientId);

    /** Asks the server to cancel a request it forwarded (a step that ran out of time). */
    void cancel(String clientId, long messageId, String byUser);

    /**
     * True while the vehicle behind the MailBox is on a call, as the live console's call state
     * has it (SURFACED, no DIVED or LINK_LOST since). That state is kept in the state store, so
     * a server started again, or a standby that took over, knows it too.
     */
    boolean onCall(String mailbox);

    /**
     * True for a MailBox that exists or has existed: a registered service has it now, or the
     * server has seen its console or kept its download folder. Queues are only for those
     * (issue 23, item 7: queues for invented MailBoxes filled the disk).
     */
    boolean knownMailbox(String mailbox);

    /**
     * Publishes a server-originated console entry for a MailBox: the workflow's progress lines
     * and its WORKFLOW_DONE / WORKFLOW_FAILED events, for watchers, the transcript and notifications.
     */
    void publish(ConsoleEntry entry);
}
