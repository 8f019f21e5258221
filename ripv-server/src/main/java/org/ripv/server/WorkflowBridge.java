package org.ripv.server;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.server.files.FileStore;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.workflow.WorkflowHost;

/** The server as the workflow runner sees it (org.ripv.server.workflow.WorkflowHost). */
final class WorkflowBridge implements WorkflowHost {
    private final RIPVServer server;

    WorkflowBridge(RIPVServer server) {
        this.server = server;
    }

    @Override
    public boolean submit(Header request) {
        return server.deliver(new IncomingServerMessage(request));
    }

    @Override
    public boolean onCall(String mailbox) {
        org.ripv.messages.SessionState s = server.sessions().console().state(mailbox);
        return s != null && s.state() == org.ripv.messages.SessionState.State.ON_CALL;
    }

    @Override
    public boolean knownMailbox(String mailbox) {
        if (server.sessions().console().state(mailbox) != null
                || java.nio.file.Files.isDirectory(server.files().downloadDir().resolve(FileStore.folderFor(mailbox)))) {
            return true;
        }
        org.ripv.naming.MailboxAddress address;
        try {
            address = org.ripv.naming.MailboxAddress.parse(mailbox);
        } catch (RuntimeException e) {
            return false;
        }
        ServiceReference ref = server.service(address.service().toString()).orElse(null);
        if (ref == null) {
            return false;
        }
        try {
            return ref.mailboxes(server.checkers(), java.time.Duration.ofSeconds(5)).get(10, java.util.concurrent.TimeUnit.SECONDS)
                    .stream().anyMatch(s -> s.address().equals(address.toString()));
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    @Override
    public PermitFile permits() {
        return server.permits();
    }

    @Override
    public FileStore files() {
        return server.files();
    }

    @Override
    public Lock lock(String mailbox) {
        OperatorLock l = server.locks().get(mailbox);
        return l == null ? null : new Lock(l.user(), l.clientId(), l.untilMillis());
    }

    @Override
    public boolean lockForWorkflow(String mailbox, String user, String clientId, long untilMillis) {
        OperatorLock mine = new OperatorLock(user, clientId, untilMillis);
        return server.locks().compute(mailbox, (k, old) -> old == null || old.expired() || old.clientId().equals(clientId)
                ? mine : old) == mine;
    }

    @Override
    public void unlockWorkflow(String mailbox, String clientId) {
        server.locks().computeIfPresent(mailbox, (k, l) -> l.clientId().equals(clientId) ? null : l);
    }

    @Override
    public void cancel(String clientId, long messageId, String byUser) {
        server.checkers().execute(() -> server.cancels().cancel(clientId, messageId, byUser));
    }

    @Override
    public void publish(ConsoleEntry entry) {
        server.publishServerEntry(entry);
    }
}
