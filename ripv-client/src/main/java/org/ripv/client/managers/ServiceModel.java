package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.SessionState;
import org.ripv.messages.TableResult;

/**
 * What one ServiceLayoutPanel shows: the service's descriptor, its MailBoxes (MAM), the COM
 * panel's state (target mailbox, status labels, history, reply transcript, progress), and the
 * fourth panel's content (DAB tables or the DAV image).
 *
 * <p>Like {@link ClientModel}, it is confined to the thread that applies changes (the event
 * thread in the GUI); only {@link GuiManager} mutates it.
 */
public final class ServiceModel {
    /** Kinds of transcript line in the COM reply area. */
    public enum LineKind { COMMAND, REPLY, ERROR, PROGRESS, NOTICE }

    /** One line (or block) of the COM reply area. */
    public record Line(LineKind kind, String text) {}

    /**
     * A request this tab sent to a service that has not had its final reply yet (a vehicle
     * command, a transfer, a query, a plot): the COM panel shows it with a Cancel button.
     *
     * @param messageId  the id {@code ?cancel} takes
     * @param command    what was sent
     * @param started    when it was sent (epoch ms)
     * @param progress   the service's latest PROGRESS for it, or null
     * @param cancelling {@code ?cancel} was sent and its outcome is not known yet
     */
    public record Running(long messageId, String command, long started, Progress progress, boolean cancelling) {
        /** "ymodem:get LOG  12 KB / 64 KB  1 KB/s  0:52 left", or "running: dir  0:07" before any progress. */
        public String text(long now) {
            if (progress != null) {
                return (cancelling ? "cancelling: " : "") + ProgressText.of(command, progress);
            }
            long s = Math.max(0, (now - started) / 1000);
            return (cancelling ? "cancelling: " : "running: ") + command + "  " + ProgressText.clock(s);
        }
    }

    /** The DAV panel's picture: the reply's bytes and, when they decode, the image. */
    public record Picture(ImageResult result, BufferedImage image) {}

    /** The reply area keeps at most this many entries; older ones scroll away. */
    public static final int MAX_LINES = 2000;
    /** Commands remembered for Up/Down recall. */
    public static final int MAX_HISTORY = 200;

    private ServiceDescriptor descriptor;
    private final List<MailboxStatus> mailboxes = new ArrayList<>();
    private String target = "";
    private String lastAction = "";
    private Priority priority = Priority.NORMAL;
    private String serviceStatus = "";
    /** Command-line history per MailBox (the key "" for lines typed with no MailBox picked). */
    private final Map<String, List<String>> histories = new HashMap<>();
    private final List<Line> transcript = new ArrayList<>();
    private Progress progress;
    private final LinkedHashMap<Long, Running> running = new LinkedHashMap<>();
    private final List<TableResult> tables = new ArrayList<>();
    private Picture picture;
    private long transcriptRevision;

    ServiceModel(ServiceDescriptor descriptor) {
        this.descriptor = descriptor;
    }

    public ServiceDescriptor descriptor() {
        return descriptor;
    }

    public String name() {
        return descriptor.name();
    }

    /** "DAB", "DAV" or "" (COM spans both rows). */
    public String panel() {
        return descriptor.panel();
    }

    public List<MailboxStatus> mailboxes() {
        return Collections.unmodifiableList(mailboxes);
    }

    /** The MailBox plain commands go to (Talking To, TT), or empty when none is picked. */
    public String target() {
        return target;
    }

    /** The last command sent (LA). */
    public String lastAction() {
        return lastAction;
    }

    /** The priority the next command is sent with (PR). */
    public Priority priority() {
        return priority;
    }

    /**
     * The target's status (SS): "available", "not available: ...", "locked by ...", and while a
     * long command runs (a transfer), "busy: WHAT (N%)" whatever the last {@code ?status} said.
     */
    public String serviceStatus() {
        if (progress != null) {
            String eta = ProgressText.eta(progress);
            // Led by the command when it is one of this tab's ("ymodem:get *.SBD · 0123.SBD").
            String what = running.values().stream().filter(r -> progress.equals(r.progress())).findFirst()
                    .map(r -> ProgressText.label(r.command(), progress)).orElse(progress.what());
            return "busy: " + what + (progress.percent() >= 0 ? " (" + progress.percent() + "%"
                    + (eta.isEmpty() ? "" : ", ETA " + eta) + ")" : "");
        }
        return serviceStatus;
    }

    /** The commands sent to the current target, oldest first (each MailBox keeps its own). */
    public List<String> history() {
        return Collections.unmodifiableList(histories.getOrDefault(target, List.of()));
    }

    public List<Line> transcript() {
        return Collections.unmodifiableList(transcript);
    }

    /** The transfer or long command in progress, or null. */
    public Progress progress() {
        return progress;
    }

    /** The requests of this tab still waiting for their final reply, oldest first. */
    public List<Running> running() {
        return List.copyOf(running.values());
    }

    /** DAB: one entry per query answered, oldest first. */
    public List<TableResult> tables() {
        return Collections.unmodifiableList(tables);
    }

    /** DAV: the latest picture, or null. */
    public Picture picture() {
        return picture;
    }

    /** Grows with every change of the transcript, so views know when to repaint it. */
    public long transcriptRevision() {
        return transcriptRevision;
    }

    /** The transcript as the reply area shows it. */
    public String transcriptText() {
        StringBuilder b = new StringBuilder();
        for (Line l : transcript) {
            switch (l.kind()) {
                case COMMAND -> b.append("> ");
                case ERROR -> b.append("Error: ");
                case NOTICE -> b.append("-- ");
                default -> { }
            }
            b.append(l.text());
            if (!l.text().endsWith("\n")) {
                b.append('\n');
            }
        }
        return b.toString();
    }

    // Mutators, package-private: only the GuiManager changes the model.

    void descriptor(ServiceDescriptor d) {
        this.descriptor = d;
    }

    void mailboxes(List<MailboxStatus> list) {
        mailboxes.clear();
        mailboxes.addAll(list);
        for (MailboxStatus m : list) {
            if (m.address().equals(target)) {
                serviceStatus = describe(m);
            }
        }
    }

    void status(MailboxStatus s) {
        for (int i = 0; i < mailboxes.size(); i++) {
            if (mailboxes.get(i).address().equals(s.address())) {
                mailboxes.set(i, s);
            }
        }
        if (s.address().equals(target)) {
            serviceStatus = describe(s);
        }
    }

    /**
     * Brings the MailBoxes' call state up to date with console entries pushed since the last
     * {@code ?mailboxes} ({@link SessionStates}); true when a badge changed.
     */
    boolean console(String mailbox, List<ConsoleEntry> entries) {
        for (int i = 0; i < mailboxes.size(); i++) {
            MailboxStatus m = mailboxes.get(i);
            if (m.address().equals(mailbox)) {
                SessionState st = m.session();
                for (ConsoleEntry e : entries) {
                    st = SessionStates.apply(st, e);
                }
                if (Objects.equals(st, m.session())) {
                    return false;
                }
                boolean moved = m.session() == null || st.state() != m.session().state();
                // A call event supersedes the service's last words on availability until it is asked again:
                // on a call the vehicle takes commands, dived or lost it does not.
                mailboxes.set(i, moved ? new MailboxStatus(m.address(), st.state() == SessionState.State.ON_CALL,
                        "", m.busy(), m.lockedBy(), st, m.running()) : m.withSession(st));
                if (mailbox.equals(target)) {
                    serviceStatus = describe(mailboxes.get(i)); // SS and the badge say the same state
                }
                return true;
            }
        }
        return false;
    }

    void target(String mailbox) {
        this.target = mailbox == null ? "" : mailbox;
        this.serviceStatus = "";
        for (MailboxStatus m : mailboxes) {
            if (m.address().equals(target)) {
                serviceStatus = describe(m);
            }
        }
    }

    void priority(Priority p) {
        this.priority = p;
    }

    void sent(String command) {
        lastAction = command;
        List<String> history = histories.computeIfAbsent(target, k -> new ArrayList<>());
        if (history.isEmpty() || !history.get(history.size() - 1).equals(command)) {
            history.add(command);
            if (history.size() > MAX_HISTORY) {
                history.remove(0);
            }
        }
        append(LineKind.COMMAND, command);
    }

    void append(LineKind kind, String text) {
        transcriptRevision++;
        transcript.add(new Line(kind, text));
        if (transcript.size() > MAX_LINES) {
            transcript.subList(0, transcript.size() - MAX_LINES).clear();
        }
    }

    void clearTranscript() {
        transcriptRevision++;
        transcript.clear();
    }

    void progress(Progress p) {
        this.progress = p;
    }

    void started(long messageId, String command, long now) {
        running.put(messageId, new Running(messageId, command, now, null, false));
    }

    /** A PROGRESS reply for a running request; false when it is not one of ours. */
    boolean progress(long messageId, Progress p) {
        Running r = running.get(messageId);
        if (r == null) {
            return false;
        }
        running.put(messageId, new Running(messageId, r.command(), r.started(), p, r.cancelling()));
        return true;
    }

    /** {@code ?cancel} sent (true) or refused (false); false when the request is not running. */
    boolean cancelling(long messageId, boolean on) {
        Running r = running.get(messageId);
        if (r == null) {
            return false;
        }
        running.put(messageId, new Running(messageId, r.command(), r.started(), r.progress(), on));
        return true;
    }

    /** The final reply came (or the request failed): the request is no longer running. */
    Running ended(long messageId) {
        return running.remove(messageId);
    }

    /** The connection went: nothing of ours runs any more. */
    void endAll() {
        running.clear();
    }

    void addTable(TableResult t) {
        tables.add(t);
    }

    void removeTable(int index) {
        tables.remove(index);
    }

    void picture(Picture p) {
        this.picture = p;
    }

    /**
     * How the SS label words a mailbox's status. A vehicle's is its call state, the one its badge
     * shows (updated by the console's events between two {@code ?mailboxes}), with the calls of
     * this run of its service counted once; the service's own words on the call (its detail) would
     * lag behind the events and count the calls again. Only on a call that takes no commands does
     * the service's detail say why.
     */
    static String describe(MailboxStatus s) {
        SessionState v = s.session();
        StringBuilder b;
        if (v != null && v.state() != SessionState.State.UNKNOWN) {
            boolean onCall = v.state() == SessionState.State.ON_CALL;
            b = new StringBuilder(onCall && s.available() ? "available" : "not available");
            b.append(" (").append(v.state().words()).append(", ").append(v.calls()).append(v.calls() == 1 ? " call" : " calls")
                    .append(" this run");
            if (onCall && !s.available() && !s.detail().isBlank()) {
                b.append("; ").append(s.detail()); // on a call yet not taking commands: the service says why
            }
            b.append(')');
        } else {
            b = new StringBuilder(s.available() ? "available" : "not available");
            if (!s.detail().isBlank()) {
                b.append(" (").append(s.detail()).append(')');
            }
        }
        if (s.busy()) {
            b.append(", busy");
        }
        if (!s.lockedBy().isBlank()) {
            b.append(", locked by ").append(s.lockedBy());
        }
        return b.toString();
    }
}
