package org.ripv.server.notify;

import java.io.IOException;
import java.net.URI;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Rights;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Delivers vehicle events to the subscriptions that want them and whose user may read the
 * MailBox (checked against the permit file in force at delivery). The subscriptions are kept by
 * {@link Subscriptions}, one try is sent by {@link Channels} (webhook or e-mail), the words by
 * {@link NoticeTexts}; this class matches events to subscriptions and tries again: a failed
 * delivery is tried again after 1, 4, 16 ... back-off units, at most {@link #ATTEMPTS} times, one
 * subscription's events in order. Nothing here runs on the caller's thread beyond queueing.
 */
public final class Notifier implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Notifier.class);
    /** Tries per delivery. */
    public static final int ATTEMPTS = 4;
    /** The pseudo-command the permit file is asked about for adding or keeping a webhook. */
    public static final String WEBHOOK = "?webhook";
    /** Deliveries waiting or in flight before new ones are dropped (and said so in the last result). */
    static final int MAX_OUTSTANDING = 10_000;

    private final Supplier<PermitFile> permits;
    private final Duration backoff;
    private final WebhookTargets targets;
    private final Subscriptions subscriptions;
    private final Channels channels;
    private final ScheduledExecutorService retries;
    private final ExecutorService http;
    private final ThreadPoolExecutor mail;
    private final AtomicInteger outstanding = new AtomicInteger();
    private volatile boolean closed;

    /**
     * @param store   where subscriptions persist (embedded: DATA/notify/subscriptions.jsonl)
     * @param smtp    the SMTP server for e-mail, or null for none
     * @param backoff the first retry's delay (later ones grow four-fold)
     * @param timeout how long a receiver may take to connect, and then to answer
     * @param targets where webhooks may go ({@code --webhook-allow})
     */
    public Notifier(StateStore store, Supplier<PermitFile> permits, Smtp smtp, Duration backoff, Duration timeout,
                    WebhookTargets targets) throws IOException {
        this.targets = targets;
        this.permits = permits;
        this.backoff = backoff;
        this.retries = Executors.newSingleThreadScheduledExecutor(named("ripv-notify-retry"));
        this.http = Executors.newFixedThreadPool(2, named("ripv-notify-http"));
        this.mail = new ThreadPoolExecutor(1, 1, 0, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), named("ripv-notify-mail"));
        this.channels = new Channels(permits, smtp, timeout, targets, http);
        this.subscriptions = new Subscriptions(store);
    }

    private static ThreadFactory named(String name) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, name + "-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    // ---- subscriptions ----

    /** Adds a subscription; returns it. Throws IllegalArgumentException for a bad target, event list or glob. */
    Subscription add(String user, Subscription.Channel channel, String target, String events, String glob)
            throws IOException {
        if (channel == Subscription.Channel.WEBHOOK) {
            String why = Channels.whyNoWebhook(permits.get(), user, target);
            if (why != null) {
                throw new Refused(why);
            }
            targets.check(checkUrl(target));
        } else {
            if (!channels.sendsMail()) {
                throw new IllegalArgumentException("this server sends no e-mail: it was started without --smtp HOST:PORT");
            }
            Channels.oneMailbox(target);
        }
        if (glob.length() > 300 || glob.isBlank()) {
            throw new IllegalArgumentException("a MailBox glob is 1-300 characters");
        }
        Set<VehicleEvent> wanted = Subscription.parseEvents(events);
        // not under a lock with the checks above: resolving a webhook's host may take seconds
        return subscriptions.add(user, channel, target, wanted, events.equalsIgnoreCase("all"), glob);
    }

    /** A subscription refused by the permit file rather than for its form. */
    static final class Refused extends IllegalArgumentException {
        Refused(String message) {
            super(message);
        }
    }

    private static URI checkUrl(String url) {
        URI u;
        try {
            u = URI.create(url);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + url + "' is not a URL: " + e.getMessage());
        }
        if (url.length() > 2000 || u.getScheme() == null || u.getHost() == null
                || !(u.getScheme().equalsIgnoreCase("http") || u.getScheme().equalsIgnoreCase("https"))) {
            throw new IllegalArgumentException("a webhook is an http:// or https:// URL with a host, not '" + url + "'");
        }
        if (u.getUserInfo() != null) {
            throw new IllegalArgumentException("a webhook URL may not carry a user name or password");
        }
        return u;
    }

    /** Removes a user's subscription; false when the user has none with that id. */
    boolean remove(String user, String id) throws IOException {
        return subscriptions.remove(user, id);
    }

    List<Subscription> of(String user) {
        return subscriptions.of(user);
    }

    private void result(Subscription s, String r) {
        if (!closed) {
            subscriptions.result(s, r);
        } else {
            s.lastResult(r);
        }
    }

    // ---- matching and retrying ----

    /**
     * The read right, checked against the rules in force at each delivery and each retry, so a
     * user who loses it (the permit file changed) stops getting that MailBox's events. Nothing
     * is written to the subscription's result: that would tell the user about a MailBox they may
     * not read.
     */
    private boolean mayRead(Subscription s, PermitFile p, String mailbox) {
        if (Rights.mayRead(p, s.user, mailbox)) {
            return true;
        }
        log.debug("subscription {} of {} may not read {}; not notified", s.id, s.user, mailbox);
        return false;
    }

    /** An event happened: queue a delivery for every subscription that wants it and may read it. */
    public void accept(ConsoleHub.Notice n) {
        ConsoleEntry e = n.event();
        PermitFile p = permits.get();
        for (Subscription s : subscriptions.all()) {
            if (!s.wants(e.event(), e.mailbox())) {
                continue;
            }
            if (!mayRead(s, p, e.mailbox())) {
                continue;
            }
            if (outstanding.incrementAndGet() > MAX_OUTSTANDING) {
                outstanding.decrementAndGet();
                result(s, "dropped " + e.event() + " of " + e.mailbox() + " at " + Instant.now()
                        + ": too many deliveries waiting");
                continue;
            }
            // One subscription's events go out in order: each waits for the one before (and its retries).
            synchronized (s) {
                s.tail = s.tail.thenCompose(v -> {
                    CompletableFuture<Void> done = new CompletableFuture<>();
                    attempt(s, n, 1, done);
                    return done;
                });
            }
        }
    }

    private void attempt(Subscription s, ConsoleHub.Notice n, int attempt, CompletableFuture<Void> done) {
        if (!subscriptions.holds(s) || closed || !mayRead(s, permits.get(), n.event().mailbox())) {
            outstanding.decrementAndGet();
            done.complete(null); // removed meanwhile, or its user lost the right to read (the permit file changed)
            return;
        }
        boolean webhook = s.channel == Subscription.Channel.WEBHOOK;
        Runnable send = webhook ? () -> channels.post(s, n, o -> ended(s, n, attempt, o, done))
                : () -> channels.mail(s, n, o -> ended(s, n, attempt, o, done));
        try {
            (webhook ? http : mail).execute(send);
        } catch (RejectedExecutionException e) {
            outstanding.decrementAndGet();
            done.complete(null);
        }
    }

    /** A try ended: the result kept, the next try scheduled after its back-off, or the delivery done. */
    private void ended(Subscription s, ConsoleHub.Notice n, int attempt, Channels.Outcome o, CompletableFuture<Void> done) {
        if (o.delivered()) {
            outstanding.decrementAndGet();
            result(s, o.how() + ": " + n.event().event() + " of " + n.event().mailbox() + " at " + Instant.now());
            done.complete(null);
            return;
        }
        String why = o.how();
        boolean retry = o.retry();
        if (retry && attempt < ATTEMPTS && !retries.isShutdown()) {
            long delay = backoff.toMillis() * (1L << (2 * (attempt - 1)));
            result(s, "failed (" + why + ") " + n.event().event() + " of " + n.event().mailbox() + " at " + Instant.now()
                    + "; try " + (attempt + 1) + " of " + ATTEMPTS + " in " + delay + " ms");
            try {
                retries.schedule(() -> attempt(s, n, attempt + 1, done), delay, TimeUnit.MILLISECONDS);
                return;
            } catch (RejectedExecutionException e) {
                // shutting down
            }
        }
        outstanding.decrementAndGet();
        result(s, "failed (" + why + ") " + n.event().event() + " of " + n.event().mailbox() + " at " + Instant.now()
                + (retry ? "; gave up after " + attempt + " tries" : ""));
        log.warn("notification {} to {} failed: {}", s.id, s.target, why);
        done.complete(null);
    }

    /** Deliveries queued or in flight (tests). */
    public int outstanding() {
        return outstanding.get();
    }

    @Override
    public void close() {
        closed = true;
        retries.shutdownNow();
        mail.shutdownNow();
        http.shutdownNow();
        try {
            mail.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
