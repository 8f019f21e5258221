package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.ripv.commands.CommandWords;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.files.FileNames;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.Rights;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The operators' workflow commands ({@code ?queue}, {@code ?receipts}; docs/workflows.md): who may
 * read a vehicle's queue and receipts, queue an uploaded workflow (checked whole, every step
 * against its owner's rights, before it is queued) or remove one; the runs themselves are
 * {@link Workflows}'.
 */
final class WorkflowCommands {
    private static final Logger log = LoggerFactory.getLogger(WorkflowCommands.class);

    private final Workflows workflows;

    WorkflowCommands(Workflows workflows) {
        this.workflows = workflows;
    }

    /** {@code ?queue MAILBOX}, {@code ?queue add MAILBOX NAME}, {@code ?queue remove MAILBOX ID}, {@code ?queue clear MAILBOX}. */
    OutgoingServerMessage queue(IncomingServerMessage request) throws IOException {
        return answer(request, Ids.FID_QUEUE, this::queueOrRefuse);
    }

    /** A command's answer, or FORBIDDEN with the reason when the rules refuse it. */
    private static OutgoingServerMessage answer(IncomingServerMessage request, String fid, Command command) throws IOException {
        try {
            return command.run(request);
        } catch (Workflows.Refused e) {
            return request.reply(Footer.error(fid, ErrorCode.FORBIDDEN, e.getMessage()).via(Workflows.SERVER));
        }
    }

    private interface Command {
        OutgoingServerMessage run(IncomingServerMessage request) throws IOException;
    }

    private OutgoingServerMessage queueOrRefuse(IncomingServerMessage request) throws IOException {
        String[] w = request.header().body().trim().split("\\s+");
        String user = request.header().origin().user();
        if (w.length == 2) {
            String mailbox = address(w[1]);
            mayRead(user, mailbox);
            return Workflows.ok(request, Ids.FID_QUEUE, listing(mailbox));
        }
        String verb = w.length > 1 ? w[1].toLowerCase(Locale.ROOT) : "";
        switch (verb) {
            case "add" -> {
                QueueAdd add = CommandWords.parse(new QueueAdd(), QUEUE_ADD, Arrays.copyOfRange(w, 2, w.length));
                boolean typed = add.typed;
                String name = add.name;
                String mailbox = address(add.mailbox);
                mayRead(user, mailbox);
                PermitFile.User u = permitted(request);
                if (!workflows.queues.has(mailbox) && !workflows.knownMailbox(mailbox)) {
                    throw new IllegalArgumentException("no MailBox " + mailbox + " exists or has existed; queues are for"
                            + " MailBoxes a service has (?mailboxes lists them)");
                }
                Workflow wf;
                try {
                    wf = read(name);
                    checkSteps(u, mailbox, wf);
                } catch (RuntimeException refused) {
                    if (typed) {
                        dropTyped(name, user);
                    }
                    throw refused;
                }
                QueuedWorkflow e = workflows.queues.add(mailbox, user, sourceOf(name), wf);
                if (workflows.onCall(mailbox)) {
                    workflows.surfaced(mailbox); // the vehicle is on a call now: run it in this call
                }
                log.info("{} queued workflow {} '{}' ({} steps, {}) for {}", user, e.id(), e.file(), wf.steps().size(),
                        wf.mode().word(), mailbox);
                String when = workflows.onCall(mailbox) ? "the vehicle is on a call: it runs now" : "it runs when the vehicle calls";
                return Workflows.ok(request, Ids.FID_QUEUE, "queued workflow " + e.id() + " '" + e.file() + "' (" + wf.steps().size()
                        + " step(s), " + wf.mode().word() + ") for " + mailbox + "; " + when + "\n" + listing(mailbox));
            }
            case "remove" -> {
                usage(w.length == 4, "?queue remove MAILBOX ID");
                String mailbox = address(w[2]);
                mayRead(user, mailbox);
                long id;
                try {
                    id = Long.parseLong(w[3]);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("ID must be a number from ?queue " + mailbox + ", got '" + w[3] + "'");
                }
                Optional<QueuedWorkflow> e = workflows.queues.get(mailbox, id);
                if (e.isEmpty()) {
                    return Workflows.error(request, ErrorCode.BAD_REQUEST, "no workflow " + id + " in the queue of " + mailbox
                            + "; ?queue " + mailbox + " lists them");
                }
                mayChange(request, e.get());
                workflows.queues.remove(mailbox, id);
                Runner running = workflows.running(mailbox);
                if (running != null && e.get().state() == QueuedWorkflow.State.RUNNING) {
                    running.cancelCurrent(user);
                }
                return Workflows.ok(request, Ids.FID_QUEUE, "removed workflow " + id + " '" + e.get().file() + "' from " + mailbox
                        + (e.get().state() == QueuedWorkflow.State.RUNNING ? " (its run stops at the next step boundary)" : "")
                        + "\n" + listing(mailbox));
            }
            case "clear" -> {
                usage(w.length == 3, "?queue clear MAILBOX");
                String mailbox = address(w[2]);
                mayRead(user, mailbox);
                List<QueuedWorkflow> all = workflows.queues.list(mailbox);
                for (QueuedWorkflow e : all) {
                    mayChange(request, e);
                }
                for (QueuedWorkflow e : all) {
                    workflows.queues.remove(mailbox, e.id());
                }
                return Workflows.ok(request, Ids.FID_QUEUE, "removed " + all.size() + " workflow(s) from " + mailbox);
            }
            default -> throw new IllegalArgumentException("usage: ?queue MAILBOX | ?queue add MAILBOX NAME | "
                    + "?queue remove MAILBOX ID | ?queue clear MAILBOX");
        }
    }

    /** {@code ?receipts MAILBOX [--last N]}. */
    OutgoingServerMessage receipts(IncomingServerMessage request, Workflows.ReceiptOptions options) throws IOException {
        return answer(request, Ids.FID_RECEIPTS, r -> receiptsOrRefuse(r, options));
    }

    private OutgoingServerMessage receiptsOrRefuse(IncomingServerMessage request, Workflows.ReceiptOptions options) throws IOException {
        int n = options.last;
        String mailbox = address(options.mailbox);
        mayRead(request.header().origin().user(), mailbox);
        List<String> last = workflows.receipts.last(mailbox, n);
        if (last.isEmpty()) {
            return Workflows.ok(request, Ids.FID_RECEIPTS, "no workflow receipts for " + mailbox + " yet");
        }
        return Workflows.ok(request, Ids.FID_RECEIPTS, last.size() + " receipt(s) for " + mailbox + ", oldest first\n\n"
                + String.join("\n", last).stripTrailing());
    }

    private String listing(String mailbox) {
        List<QueuedWorkflow> list = workflows.queues.list(mailbox);
        if (list.isEmpty()) {
            return "the queue of " + mailbox + " is empty";
        }
        StringBuilder b = new StringBuilder(list.size() + " workflow(s) queued for " + mailbox + ", in the order they run:\n");
        b.append(String.format("%4s  %-10s %-12s %s%n", "ID", "OWNER", "MODE", "FILE, STATE"));
        Runner running = workflows.running(mailbox);
        String request = running == null ? null : running.currentRequest();
        for (QueuedWorkflow e : list) {
            b.append(e.describe()).append(String.format("  (added %s)", Instant.ofEpochMilli(e.added())));
            if (e.state() == QueuedWorkflow.State.RUNNING && request != null) {
                b.append("  [step request: ?cancel ").append(request).append(']');
            }
            b.append('\n');
        }
        return b.toString().stripTrailing();
    }

    private static String address(String text) {
        try {
            return MailboxAddress.parse(text).toString();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not a MailBox address (" + e.getMessage() + "); ?mailboxes lists them");
        }
    }

    private static void usage(boolean ok, String usage) {
        if (!ok) {
            throw new IllegalArgumentException("usage: " + usage);
        }
    }

    /**
     * A queue and its receipts show what a vehicle is told and what it answered: reading them
     * needs the read right on the MailBox, as watching and {@code ?history} do ({@link Rights}).
     */
    private void mayRead(String user, String mailbox) {
        String why = Rights.whyNotRead(workflows.host.permits(), user, mailbox);
        if (why != null) {
            throw new Workflows.Refused(why);
        }
    }

    /** The {@code ?queue …} command itself must be allowed (service RIPVServer, as for ?lock). */
    private PermitFile.User permitted(IncomingServerMessage request) {
        String user = request.header().origin().user();
        PermitFile p = workflows.host.permits();
        PermitFile.User u = p.user(user).orElseThrow(() -> new Workflows.Refused("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = p.decide(u, Workflows.SERVER, "", request.header().body().trim());
        if (!d.allowed()) {
            throw new Workflows.Refused("user '" + user + "' may not change workflow queues (" + d.because() + ")");
        }
        return u;
    }

    /**
     * The owner removes their entry when the permit file allows them the command itself; anyone
     * else's needs a rule allowing {@code ?queue remove-any}.
     */
    private void mayChange(IncomingServerMessage request, QueuedWorkflow e) {
        String user = request.header().origin().user();
        if (e.owner().equals(user)) {
            permitted(request);
            return;
        }
        PermitFile p = workflows.host.permits();
        Optional<PermitFile.User> u = p.user(user);
        if (u.isEmpty() || !p.decide(u.get(), Workflows.SERVER, "", "?queue remove-any").allowed()) {
            throw new Workflows.Refused("workflow " + e.id() + " belongs to " + e.owner() + "; only they, or a user the permit file allows "
                    + "'?queue remove-any', may remove it");
        }
    }

    /** Every request the workflow will send must be one its owner may send (write rights on the MailBox). */
    private void checkSteps(PermitFile.User u, String mailbox, Workflow wf) {
        PermitFile p = workflows.host.permits();
        for (Step s : wf.steps()) {
            String target = s.to().isEmpty() ? mailbox : address(s.to());
            String command = switch (s.kind()) {
                case SEND, VIS -> s.text();
                case GET, PUT -> s.transferWord() + " " + String.join(" ", s.names());
                case INGEST -> "ingest";
                case WAIT_FOR, NOTIFY -> null;
            };
            if (command == null) {
                continue;
            }
            MailboxAddress a = MailboxAddress.parse(target);
            PermitFile.Decision d = p.decide(u, a.service().service(), a.handle(), command);
            if (!d.allowed()) {
                throw new Workflows.Refused(wf.name() + ":" + s.line() + ": user '" + u.name() + "' may not send '" + command + "' to "
                        + target + " (" + d.because() + "), so the workflow could never run");
            }
            if (s.kind() == Step.Kind.GET && !s.all() && !p.decide(u, a.service().service(), a.handle(), "dir").allowed()) {
                throw new Workflows.Refused(wf.name() + ":" + s.line() + ": " + s.transferWord() + " lists the vehicle's files with 'dir', which user '"
                        + u.name() + "' may not send to " + target);
            }
        }
    }

    private String sourceOf(String name) throws IOException {
        byte[] bytes = workflows.host.files().readUpload(name);
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new WorkflowException(name, 0, "not UTF-8 text: a workflow file is text (docs/workflows.md)");
        }
    }

    /**
     * The word after {@code ?queue add MAILBOX NAME} that says NAME was uploaded only to be queued
     * (typed in the GUI's editor or the web page): when the workflow is refused, the file leaves
     * the upload store again, so drafts that did not parse do not pile up there.
     */
    static final String TYPED = "--typed";

    /** The words of {@code ?queue add}, parsed as every {@code ?} command's options are (picocli, no {@code @file}). */
    static final class QueueAdd {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Parameters(index = "1", paramLabel = "NAME")
        String name;
        @Option(names = TYPED, description = "the workflow was typed in an editor: a refused one leaves the upload store")
        boolean typed;
    }

    private static final String QUEUE_ADD = CommandWords.usage("?queue add", new QueueAdd());

    /** Deletes a refused typed workflow, when the user who queues it uploaded it (no one else's file goes). */
    private void dropTyped(String name, String user) {
        try {
            if (user.equals(workflows.host.files().owner(name))) {
                workflows.host.files().delete(name);
                log.info("{}: deleted the refused typed workflow {} from the upload store", user, name);
            }
        } catch (IOException | RuntimeException e) {
            log.warn("could not delete the refused typed workflow {}: {}", name, e.toString());
        }
    }

    /** {@link Workflows#queueGenerated}: as {@code ?queue add}, the text given rather than uploaded. */
    long queueGenerated(String mailbox, String user, String label, String source) throws IOException {
        mayRead(user, mailbox);
        PermitFile p = workflows.host.permits();
        PermitFile.User u = p.user(user).orElseThrow(() -> new Workflows.Refused("user '" + user + "' is no longer in the permit file"));
        Workflow wf = WorkflowParser.parse(label, source, workflows::uploadExists);
        checkSteps(u, mailbox, wf);
        QueuedWorkflow e = workflows.queues.add(mailbox, user, source, wf);
        if (workflows.onCall(mailbox)) {
            workflows.surfaced(mailbox);
        }
        log.info("{} queued workflow {} '{}' for {} (generated)", user, e.id(), e.file(), mailbox);
        return e.id();
    }

    /** Reads and parses an uploaded workflow file; refused whole with line and reason. */
    private Workflow read(String name) throws IOException {
        FileNames.check(name);
        if (!Files.isRegularFile(workflows.host.files().uploadDir().resolve(name))) {
            throw new NoSuchFileException("no file '" + name + "' in the upload store; upload the workflow first (put FILE)");
        }
        long size = Files.size(workflows.host.files().uploadDir().resolve(name));
        if (size > WorkflowParser.MAX_CHARS * 4L) {
            throw new WorkflowException(name, 0, "the file is " + size + " bytes; too large for a workflow");
        }
        return WorkflowParser.parse(name, sourceOf(name), workflows::uploadExists);
    }
}
