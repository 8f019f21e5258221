package org.ripv.server.workflow;

import java.nio.file.Files;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.SessionState;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.files.FileStore;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.RequestCancels;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;
import org.ripv.server.session.ConsoleHub;

/** The server as the workflow runner sees it (org.ripv.server.workflow.WorkflowHost). */
public final class WorkflowBridge implements WorkflowHost {
    private final Predicate<IncomingServerMessage> postOffice;
    private final ConsoleHub console;
    private final Consumer<ConsoleEntry> publish;
    private final FileStore files;
    private final ServiceRegistry services;
    private final Executor checkers;
    private final Supplier<PermitFile> permits;
    private final Map<String, OperatorLock> locks;
    private final RequestCancels cancels;

    /**
     * @param postOffice delivers a step's request to the RIPV Post Office; false when it is full
     * @param console    the vehicles' call state
     * @param publish    where the runner's own console entries go
     * @param checkers   where calls to services run
     */
    public WorkflowBridge(Predicate<IncomingServerMessage> postOffice, ConsoleHub console, Consumer<ConsoleEntry> publish,
                          FileStore files, ServiceRegistry services, Executor checkers, Supplier<PermitFile> permits,
                          Map<String, OperatorLock> locks, RequestCancels cancels) {
        this.postOffice = postOffice;
        this.console = console;
        this.publish = publish;
        this.files = files;
        this.services = services;
        this.checkers = checkers;
        this.permits = permits;
        this.locks = locks;
        this.cancels = cancels;
    }

    @Override
    public boolean submit(Header request) {
        return postOffice.test(new IncomingServerMessage(request));
    }

    @Override
    public boolean onCall(String mailbox) {
        SessionState s = console.state(mailbox);
        return s != null && s.state() == SessionState.State.ON_CALL;
    }

    @Override
    public boolean knownMailbox(String mailbox) {
        if (console.state(mailbox) != null
                || Files.isDirectory(files.downloadDir().resolve(FileStore.folderFor(mailbox)))) {
            return true;
        }
        MailboxAddress address;
        try {
            address = MailboxAddress.parse(mailbox);
        } catch (RuntimeException e) {
            return false;
        }
        ServiceReference ref = services.find(address.service().toString()).orElse(null);
        if (ref == null) {
            return false;
        }
        try {
            return ref.mailboxes(checkers, Duration.ofSeconds(5)).get(10, TimeUnit.SECONDS)
                    .stream().anyMatch(s -> s.address().equals(address.toString()));
        } catch (ExecutionException | TimeoutException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    @Override
    public PermitFile permits() {
        return permits.get();
    }

    @Override
    public FileStore files() {
        return this.files;
    }

    @Override
    public Lock lock(String mailbox) {
        OperatorLock l = locks.get(mailbox);
        return l == null ? null : new Lock(l.user(), l.clientId(), l.untilMillis());
    }

    @Override
    public boolean lockForWorkflow(String mailbox, String user, String clientId, long untilMillis) {
        OperatorLock mine = new OperatorLock(user, clientId, untilMillis);
        return locks.compute(mailbox, (k, old) -> old == null || old.expired() || old.clientId().equals(clientId)
                ? mine : old) == mine;
    }

    @Override
    public void unlockWorkflow(String mailbox, String clientId) {
        locks.computeIfPresent(mailbox, (k, l) -> l.clientId().equals(clientId) ? null : l);
    }

    @Override
    public void cancel(String clientId, long messageId, String byUser) {
        checkers.execute(() -> cancels.cancel(clientId, messageId, byUser));
    }

    @Override
    public void publish(ConsoleEntry entry) {
        publish.accept(entry);
    }
}
