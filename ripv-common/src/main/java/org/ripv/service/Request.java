package org.ripv.service;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import org.ripv.messages.Attachment;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.TableResult;
import org.ripv.post.MailBox;

/** One command as a handler sees it, with a way to report progress on long work. */
public final class Request {
    private final IncomingServiceMessage message;
    private final MailBox<IncomingServiceMessage, OutgoingServiceMessage> box;
    private final String sid;
    private final String hop;
    /** Pages sent that the reader has not taken yet may number at most this (see {@link #page}). */
    static final int PAGES_IN_FLIGHT = 2;
    private final Semaphore pageCredits = new Semaphore(PAGES_IN_FLIGHT);
    private volatile boolean pagesStopped;

    Request(IncomingServiceMessage message, MailBox<IncomingServiceMessage, OutgoingServiceMessage> box,
            String sid, String hop) {
        this.message = message;
        this.box = box;
        this.sid = sid;
        this.hop = hop;
    }

    /** The command line, e.g. {@code dir} or {@code SELECT * FROM mission}. */
    public String command() {
        return message.header().body();
    }

    /** The command's words after the first, split on white space. */
    public List<String> arguments() {
        String[] words = command().trim().split("\\s+");
        return words.length <= 1 ? List.of() : List.of(words).subList(1, words.length);
    }

    /** The user the server logged in, never what a client claimed. */
    public String user() {
        return message.header().origin().user();
    }

    /** The user's roles from the server's permit file. */
    public List<String> roles() {
        return message.header().roles();
    }

    public Priority priority() {
        return message.header().priority();
    }

    /** The address of the MailBox running the command. */
    public String mailbox() {
        return box.address();
    }

    /** The file the server attached from its upload directory, if any. */
    public Optional<Attachment> attachment() {
        return Optional.ofNullable(message.header().attachment());
    }

    public IncomingServiceMessage message() {
        return message;
    }

    /** Sends a PROGRESS reply now; the final reply still comes from the handler's return. */
    public void progress(String text, Progress progress) {
        box.post(message.reply(Footer.progress(sid, text, progress).via(hop)));
    }

    /**
     * Sends the next page of a table ({@link org.ripv.messages.TablePages}) once the reader has
     * taken all but {@value #PAGES_IN_FLIGHT} - 1 of the pages sent before, so a result never
     * waits anywhere on its way in more than that many pages: the server says when a page went out
     * to the client's socket (for a reader in this JVM, when the sink took it). The final reply,
     * the handler's return, carries the rows after the last page.
     *
     * @param wait how long the reader may take no page before the handler gives up
     * @throws PagesStopped when the request was cancelled, or the reader took nothing for {@code wait}
     * @throws InterruptedException when the thread was interrupted (a cancel, for some handlers)
     */
    public void page(String text, TableResult rows, Duration wait) throws PagesStopped, InterruptedException {
        if (!pageCredits.tryAcquire(wait.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new PagesStopped(false, "the reader took no rows for " + wait.toSeconds() + " s");
        }
        if (pagesStopped) {
            throw new PagesStopped(true, "the request was cancelled");
        }
        box.post(message.reply(Footer.progress(sid, text, rows).via(hop)));
    }

    /** The reader took a page: one more may go ({@link #page}). */
    void pageTaken() {
        pageCredits.release();
    }

    /** A cancel: a handler waiting in {@link #page} stops waiting, and no page goes out after it. */
    void stopPages() {
        pagesStopped = true;
        pageCredits.release(PAGES_IN_FLIGHT + 1);
    }

    /** Why {@link #page} sent nothing: a cancel, or a reader that stopped taking pages. */
    public static final class PagesStopped extends Exception {
        private static final long serialVersionUID = 1L;
        private final boolean cancelled;

        PagesStopped(boolean cancelled, String message) {
            super(message);
            this.cancelled = cancelled;
        }

        /** True when a cancel stopped the pages, false when the reader stopped taking them. */
        public boolean cancelled() {
            return cancelled;
        }
    }
}
