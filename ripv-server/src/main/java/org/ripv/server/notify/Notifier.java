package org.ripv.server.notify;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Date;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
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
import jakarta.mail.Message;
import jakarta.mail.MessagingException;
import jakarta.mail.Session;
import jakarta.mail.Transport;
import jakarta.mail.internet.AddressException;
import jakarta.mail.internet.InternetAddress;
import jakarta.mail.internet.MimeMessage;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Entries;
import org.ripv.json.Json;
import org.ripv.server.session.Rights;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Delivers vehicle events to the subscriptions that want them and whose user may read the
 * MailBox (checked against the permit file in force at delivery). Webhooks go out with the JDK's
 * asynchronous HTTP client (connect and response time-outs), e-mail on a thread of its own; a
 * failed delivery is tried again after 1, 4, 16 ... back-off units, at most {@link #ATTEMPTS}
 * times. Nothing here runs on the caller's thread beyond queueing.
 */
public final class Notifier implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Notifier.class);
    /** Tries per delivery. */
    public static final int ATTEMPTS = 4;
    /** The pseudo-command the permit file is asked about for adding or keeping a webhook. */
    public static final String WEBHOOK = "?webhook";
    private static final String SERVICE = "RIPVServer";
    /** Deliveries waiting or in flight before new ones are dropped (and said so in the last result). */
    static final int MAX_OUTSTANDING = 10_000;
    /** Subscriptions one user may hold. */
    static final int MAX_PER_USER = 50;

    private final StateStore store;
    private final Supplier<PermitFile> permits;
    private final Smtp smtp;
    private final Duration backoff;
    private final Duration timeout;
    private final WebhookTargets targets;
    private final Map<String, Subscription> subscriptions = new ConcurrentHashMap<>();
    private final ScheduledExecutorService retries;
    private final ExecutorService http;
    private final ThreadPoolExecutor mail;
    private final HttpClient client;
    private final AtomicInteger outstanding = new AtomicInteger();
    private final SecureRandom random = new SecureRandom();
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
        this.store = store;
        this.targets = targets;
        this.permits = permits;
        this.smtp = smtp;
        this.backoff = backoff;
        this.timeout = timeout;
        this.retries = Executors.newSingleThreadScheduledExecutor(named("ripv-notify-retry"));
        this.http = Executors.newFixedThreadPool(2, named("ripv-notify-http"));
        this.mail = new ThreadPoolExecutor(1, 1, 0, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), named("ripv-notify-mail"));
        this.client = HttpClient.newBuilder().connectTimeout(timeout).executor(http)
                .followRedirects(HttpClient.Redirect.NEVER).build();
        load();
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

    /**
     * The one mailbox an e-mail subscription goes to: {@code local@domain} and nothing else. A
     * group ({@code g:a@x.org,c@y.org;}), a list, a display name or angle brackets are refused:
     * one subscription mails one person, within the per-user cap (issue 23, item 9: a group was
     * taken as one address and mailed every member). Checked when subscribing and again at every
     * delivery, for subscriptions stored before.
     */
    static InternetAddress oneMailbox(String target) {
        String t = target == null ? "" : target.strip();
        try {
            InternetAddress[] all = InternetAddress.parse(t, true);
            if (all.length == 1 && !all[0].isGroup() && all[0].getPersonal() == null && t.equals(all[0].getAddress())
                    && t.indexOf(',') < 0 && t.indexOf(';') < 0 && t.indexOf(':') < 0 && t.indexOf('<') < 0) {
                all[0].validate();
                return all[0];
            }
        } catch (AddressException e) {
            throw new IllegalArgumentException("'" + target + "' is not an e-mail address: " + e.getMessage());
        }
        throw new IllegalArgumentException("'" + target + "' is not one e-mail address: a subscription mails one mailbox"
                + " (name@example.org), not a group or a list; add one subscription per person");
    }

    /** Adds a subscription; returns it. Throws IllegalArgumentException for a bad target, event list or glob. */
    Subscription add(String user, Subscription.Channel channel, String target, String events, String glob)
            throws IOException {
        if (channel == Subscription.Channel.WEBHOOK) {
            String why = whyNoWebhook(permits.get(), user, target);
            if (why != null) {
                throw new Refused(why);
            }
            targets.check(checkUrl(target));
        } else {
            if (smtp == null) {
                throw new IllegalArgumentException("this server sends no e-mail: it was started without --smtp HOST:PORT");
            }
            oneMailbox(target);
        }
        if (glob.length() > 300 || glob.isBlank()) {
            throw new IllegalArgumentException("a MailBox glob is 1-300 characters");
        }
        Set<VehicleEvent> wanted = Subscription.parseEvents(events);
        synchronized (this) { // not around the checks above: resolving a webhook's host may take seconds
            if (subscriptions.values().stream().filter(s -> s.user.equals(user)).count() >= MAX_PER_USER) {
                throw new IllegalArgumentException("a user may hold at most " + MAX_PER_USER + " subscriptions; ?notify remove some");
            }
            String id;
            do {
                byte[] b = new byte[4];
                random.nextBytes(b);
                id = "n" + HexFormat.of().formatHex(b);
            } while (subscriptions.containsKey(id));
            Subscription s = new Subscription(id, user, channel, target, wanted, events.equalsIgnoreCase("all"), glob);
            subscriptions.put(id, s);
            save();
            return s;
        }
    }

    /**
     * A webhook lets its owner make the server send HTTP requests, so it is a right of its own:
     * the pseudo-command {@code ?webhook URL} of service RIPVServer (docs/permit.md). Null when allowed.
     */
    static String whyNoWebhook(PermitFile p, String user, String url) {
        PermitFile.User u = p.user(user).orElse(null);
        if (u == null) {
            return "user '" + user + "' is no longer in the permit file";
        }
        PermitFile.Decision d = p.decide(u, SERVICE, "", WEBHOOK + " " + url);
        return d.allowed() ? null : "user '" + user + "' may not add webhooks (" + d.because()
                + "); e-mail notifications need no extra right";
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
    synchronized boolean remove(String user, String id) throws IOException {
        Subscription s = subscriptions.get(id);
        if (s == null || !s.user.equals(user)) {
            return false;
        }
        subscriptions.remove(id);
        save();
        return true;
    }

    List<Subscription> of(String user) {
        return subscriptions.values().stream().filter(s -> s.user.equals(user)).sorted((a, b) -> a.id.compareTo(b.id)).toList();
    }

    private void load() throws IOException {
        Optional<StateStore.Stored> stored = store.loadSubscriptions();
        if (stored.isEmpty()) {
            return;
        }
        int n = 0;
        for (String line : stored.get().text().split("\n")) {
            n++;
            if (line.isBlank()) {
                continue;
            }
            try {
                Subscription s = Subscription.fromJson(line);
                subscriptions.put(s.id, s);
            } catch (IllegalArgumentException e) {
                log.warn("{}:{}: ignoring an unreadable subscription: {}", stored.get().where(), n, e.getMessage());
            }
        }
    }

    /** Replaces the stored subscriptions whole (embedded: an owner-only file; it names addresses and URLs). */
    private synchronized void save() throws IOException {
        StringBuilder b = new StringBuilder();
        subscriptions.values().stream().sorted((a, c) -> a.id.compareTo(c.id)).forEach(s -> b.append(s.toJson()).append('\n'));
        store.saveSubscriptions(b.toString());
    }

    private void result(Subscription s, String r) {
        s.lastResult(r);
        if (closed || !subscriptions.containsKey(s.id)) {
            return;
        }
        try {
            save();
        } catch (IOException e) {
            log.warn("could not save the subscriptions: {}", e.toString());
        }
    }

    // ---- delivery ----

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
        for (Subscription s : subscriptions.values()) {
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
        if (!subscriptions.containsKey(s.id) || closed || !mayRead(s, permits.get(), n.event().mailbox())) {
            outstanding.decrementAndGet();
            done.complete(null); // removed meanwhile, or its user lost the right to read (the permit file changed)
            return;
        }
        if (s.channel == Subscription.Channel.WEBHOOK) {
            try {
                http.execute(() -> post(s, n, attempt, done));
            } catch (RejectedExecutionException e) {
                outstanding.decrementAndGet();
                done.complete(null);
            }
        } else {
            try {
                mail.execute(() -> mail(s, n, attempt, done));
            } catch (RejectedExecutionException e) {
                outstanding.decrementAndGet();
                done.complete(null);
            }
        }
    }

    private void post(Subscription s, ConsoleHub.Notice n, int attempt, CompletableFuture<Void> done) {
        // Checked again at each delivery: the right may have been taken away, and a name may now
        // resolve somewhere else (this narrows DNS rebinding to the gap before the connect).
        String refusal = whyNoWebhook(permits.get(), s.user, s.target);
        if (refusal == null) {
            try {
                targets.check(URI.create(s.target));
            } catch (IllegalArgumentException e) {
                refusal = e.getMessage();
            }
        }
        if (refusal != null) {
            failed(s, n, attempt, "refused: " + refusal, false, done);
            return;
        }
        HttpRequest req;
        try {
            req = HttpRequest.newBuilder(URI.create(s.target)).timeout(timeout)
                    .header("Content-Type", "application/json; charset=utf-8")
                    .header("User-Agent", "RIPV-notify/1")
                    .POST(HttpRequest.BodyPublishers.ofString(webhookBody(s, n), StandardCharsets.UTF_8)).build();
        } catch (IllegalArgumentException e) {
            failed(s, n, attempt, "bad URL: " + e.getMessage(), false, done);
            return;
        }
        client.sendAsync(req, HttpResponse.BodyHandlers.discarding()).whenComplete((resp, err) -> {
            if (err != null) {
                Throwable c = err instanceof CompletionException && err.getCause() != null ? err.getCause() : err;
                failed(s, n, attempt, c.getClass().getSimpleName() + (c.getMessage() == null ? "" : ": " + c.getMessage()), true,
                        done);
            } else if (resp.statusCode() / 100 == 2) {
                delivered(s, n, "ok " + resp.statusCode(), done);
            } else {
                failed(s, n, attempt, "HTTP " + resp.statusCode(), resp.statusCode() >= 500 || resp.statusCode() == 429, done);
            }
        });
    }

    private void mail(Subscription s, ConsoleHub.Notice n, int attempt, CompletableFuture<Void> done) {
        try {
            Properties props = new Properties();
            props.put("mail.smtp.host", smtp.host());
            props.put("mail.smtp.port", String.valueOf(smtp.port()));
            props.put("mail.smtp.connectiontimeout", String.valueOf(timeout.toMillis()));
            props.put("mail.smtp.timeout", String.valueOf(timeout.toMillis()));
            props.put("mail.smtp.writetimeout", String.valueOf(timeout.toMillis()));
            props.put("mail.smtp.auth", String.valueOf(smtp.user() != null));
            props.put("mail.smtp.starttls.enable", String.valueOf(smtp.startTls()));
            props.put("mail.smtp.starttls.required", String.valueOf(smtp.startTls()));
            Session session = Session.getInstance(props);
            MimeMessage m = new MimeMessage(session);
            m.setFrom(new InternetAddress(smtp.from()));
            m.setRecipient(Message.RecipientType.TO, oneMailbox(s.target));
            m.setSubject("[RIPV] " + vehicle(n.event().mailbox()) + " " + n.event().event(), "UTF-8");
            m.setText(mailBody(n), "UTF-8");
            m.setSentDate(new Date());
            if (smtp.user() != null) {
                Transport.send(m, smtp.user(), smtp.password());
            } else {
                Transport.send(m);
            }
            delivered(s, n, "ok (mail accepted by " + smtp.host() + ")", done);
        } catch (MessagingException | RuntimeException e) {
            failed(s, n, attempt, e.getClass().getSimpleName() + ": " + e.getMessage(), true, done);
        }
    }

    private void delivered(Subscription s, ConsoleHub.Notice n, String how, CompletableFuture<Void> done) {
        outstanding.decrementAndGet();
        result(s, how + ": " + n.event().event() + " of " + n.event().mailbox() + " at " + Instant.now());
        done.complete(null);
    }

    private void failed(Subscription s, ConsoleHub.Notice n, int attempt, String why, boolean retry,
                        CompletableFuture<Void> done) {
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

    static String vehicle(String mailbox) {
        int at = mailbox.lastIndexOf('>');
        return at >= 0 && at < mailbox.length() - 1 ? mailbox.substring(at + 1) : mailbox;
    }

    static String webhookBody(Subscription s, ConsoleHub.Notice n) {
        ConsoleEntry e = n.event();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("subscription", s.id);
        m.put("time", Instant.ofEpochMilli(e.time()).toString());
        m.put("mailbox", e.mailbox());
        m.put("vehicle", vehicle(e.mailbox()));
        m.put("event", e.event().name());
        m.put("text", e.text());
        if (!e.user().isEmpty()) {
            m.put("user", e.user());
        }
        SessionState st = n.state();
        Double lat = e.lat() != null ? e.lat() : st == null ? null : st.lat();
        Double lon = e.lon() != null ? e.lon() : st == null ? null : st.lon();
        if (lat != null && lon != null) {
            m.put("lat", lat);
            m.put("lon", lon);
        }
        if (st != null) {
            m.put("state", st.state().name().toLowerCase(Locale.ROOT));
            m.put("calls", st.calls());
            if (st.lastContact() > 0) {
                m.put("lastContact", Instant.ofEpochMilli(st.lastContact()).toString());
            }
        }
        return Json.write(m);
    }

    static String mailBody(ConsoleHub.Notice n) {
        ConsoleEntry e = n.event();
        SessionState st = n.state();
        StringBuilder b = new StringBuilder();
        b.append("Vehicle:  ").append(vehicle(e.mailbox())).append('\n');
        b.append("MailBox:  ").append(e.mailbox()).append('\n');
        b.append("Event:    ").append(e.event()).append(e.text().isEmpty() ? "" : " (" + e.text() + ")").append('\n');
        b.append("Time:     ").append(Instant.ofEpochMilli(e.time())).append('\n');
        Double lat = e.lat() != null ? e.lat() : st == null ? null : st.lat();
        Double lon = e.lon() != null ? e.lon() : st == null ? null : st.lon();
        b.append("Position: ").append(lat != null && lon != null
                ? String.format(Locale.ROOT, "%.5f, %.5f", lat, lon) : "unknown").append('\n');
        if (st != null) {
            b.append("State:    ").append(st.state().words()).append(", ").append(st.calls()).append(" call(s)");
            if (st.lastContact() > 0) {
                b.append(", last contact ").append(Instant.ofEpochMilli(st.lastContact()));
            }
            b.append('\n');
        }
        List<ConsoleEntry> lines = new ArrayList<>(n.lastLines());
        if (!lines.isEmpty()) {
            b.append("\nLast lines:\n");
            lines.forEach(l -> b.append("  ").append(Entries.toText(l)).append('\n'));
        }
        b.append("\n-- RIPV (?notify list shows your subscriptions; ?notify remove ID ends one)\n");
        return b.toString();
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
