package org.ripv.server.notify;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Date;
import java.util.Properties;
import java.util.concurrent.CompletionException;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import java.util.function.Supplier;
import jakarta.mail.Message;
import jakarta.mail.MessagingException;
import jakarta.mail.Session;
import jakarta.mail.Transport;
import jakarta.mail.internet.AddressException;
import jakarta.mail.internet.InternetAddress;
import jakarta.mail.internet.MimeMessage;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.ConsoleHub;

/**
 * Sends one notification once: a webhook with the JDK's asynchronous HTTP client (connect and
 * response time-outs, no redirects), an e-mail through the SMTP server. Says how it went
 * ({@link Outcome}); trying again is the {@link Notifier}'s business.
 */
final class Channels {
    private static final String SERVICE = "RIPVServer";

    /** How one try went: delivered, or failed and whether another try may help. */
    record Outcome(boolean delivered, String how, boolean retry) {
        static Outcome delivered(String how) {
            return new Outcome(true, how, false);
        }

        static Outcome failed(String why, boolean retry) {
            return new Outcome(false, why, retry);
        }
    }

    private final Supplier<PermitFile> permits;
    private final Smtp smtp;
    private final Duration timeout;
    private final WebhookTargets targets;
    private final HttpClient client;

    /**
     * @param http    where the HTTP client runs
     * @param timeout how long a receiver may take to connect, and then to answer
     */
    Channels(Supplier<PermitFile> permits, Smtp smtp, Duration timeout, WebhookTargets targets, Executor http) {
        this.permits = permits;
        this.smtp = smtp;
        this.timeout = timeout;
        this.targets = targets;
        this.client = HttpClient.newBuilder().connectTimeout(timeout).executor(http)
                .followRedirects(HttpClient.Redirect.NEVER).build();
    }

    boolean sendsMail() {
        return smtp != null;
    }

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

    /**
     * A webhook lets its owner make the server send HTTP requests, so it is a right of its own:
     * the pseudo-command {@code ?webhook URL} of service RIPVServer (docs/permit.md). Null when allowed.
     */
    static String whyNoWebhook(PermitFile p, String user, String url) {
        PermitFile.User u = p.user(user).orElse(null);
        if (u == null) {
            return "user '" + user + "' is no longer in the permit file";
        }
        PermitFile.Decision d = p.decide(u, SERVICE, "", Notifier.WEBHOOK + " " + url);
        return d.allowed() ? null : "user '" + user + "' may not add webhooks (" + d.because()
                + "); e-mail notifications need no extra right";
    }

    void post(Subscription s, ConsoleHub.Notice n, Consumer<Outcome> outcome) {
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
            outcome.accept(Outcome.failed("refused: " + refusal, false));
            return;
        }
        HttpRequest req;
        try {
            req = HttpRequest.newBuilder(URI.create(s.target)).timeout(timeout)
                    .header("Content-Type", "application/json; charset=utf-8")
                    .header("User-Agent", "RIPV-notify/1")
                    .POST(HttpRequest.BodyPublishers.ofString(NoticeTexts.webhookBody(s, n), StandardCharsets.UTF_8)).build();
        } catch (IllegalArgumentException e) {
            outcome.accept(Outcome.failed("bad URL: " + e.getMessage(), false));
            return;
        }
        client.sendAsync(req, HttpResponse.BodyHandlers.discarding()).whenComplete((resp, err) -> {
            if (err != null) {
                Throwable c = err instanceof CompletionException && err.getCause() != null ? err.getCause() : err;
                outcome.accept(Outcome.failed(c.getClass().getSimpleName() + (c.getMessage() == null ? "" : ": " + c.getMessage()),
                        true));
            } else if (resp.statusCode() / 100 == 2) {
                outcome.accept(Outcome.delivered("ok " + resp.statusCode()));
            } else {
                outcome.accept(Outcome.failed("HTTP " + resp.statusCode(), resp.statusCode() >= 500 || resp.statusCode() == 429));
            }
        });
    }

    void mail(Subscription s, ConsoleHub.Notice n, Consumer<Outcome> outcome) {
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
            m.setSubject(NoticeTexts.subject(n), "UTF-8");
            m.setText(NoticeTexts.mailBody(n), "UTF-8");
            m.setSentDate(new Date());
            if (smtp.user() != null) {
                Transport.send(m, smtp.user(), smtp.password());
            } else {
                Transport.send(m);
            }
            outcome.accept(Outcome.delivered("ok (mail accepted by " + smtp.host() + ")"));
        } catch (MessagingException | RuntimeException e) {
            outcome.accept(Outcome.failed(e.getClass().getSimpleName() + ": " + e.getMessage(), true));
        }
    }
}
