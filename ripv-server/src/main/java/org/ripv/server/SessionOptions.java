package org.ripv.server;

import java.time.Duration;
import org.ripv.server.notify.Smtp;
import org.ripv.server.notify.WebhookTargets;

/**
 * How the server keeps vehicle sessions (docs/sessions.md): transcript rotation and age, the
 * SMTP server for e-mail notifications, and notification retry timing.
 *
 * @param transcriptFileBytes a transcript file grows to about this size before the next starts
 * @param keepDays            transcript files of days older than this are deleted
 * @param smtp                the SMTP server for e-mail notifications, or null for none
 * @param notifyBackoff       the first retry's delay (later retries wait four times longer each)
 * @param notifyTimeout       how long a webhook or SMTP server may take to connect, and then to answer
 * @param webhooks            where webhooks may go (public addresses only unless {@code --webhook-allow})
 */
public record SessionOptions(long transcriptFileBytes, int keepDays, Smtp smtp, Duration notifyBackoff,
                             Duration notifyTimeout, WebhookTargets webhooks) {
    public static final long DEFAULT_FILE_BYTES = 64L * 1024 * 1024;
    public static final int DEFAULT_KEEP_DAYS = 90;

    public SessionOptions {
        if (transcriptFileBytes < 4096) {
            throw new IllegalArgumentException("a transcript file must be allowed at least 4096 bytes");
        }
        if (keepDays < 1) {
            throw new IllegalArgumentException("transcripts must be kept at least 1 day");
        }
        if (webhooks == null) {
            webhooks = WebhookTargets.PUBLIC_ONLY;
        }
    }

    public static SessionOptions defaults() {
        return new SessionOptions(DEFAULT_FILE_BYTES, DEFAULT_KEEP_DAYS, null, Duration.ofSeconds(5), Duration.ofSeconds(10),
                WebhookTargets.PUBLIC_ONLY);
    }

    public SessionOptions withSmtp(Smtp s) {
        return new SessionOptions(transcriptFileBytes, keepDays, s, notifyBackoff, notifyTimeout, webhooks);
    }

    public SessionOptions withTranscripts(long fileBytes, int days) {
        return new SessionOptions(fileBytes, days, smtp, notifyBackoff, notifyTimeout, webhooks);
    }

    public SessionOptions withNotifyTiming(Duration backoff, Duration timeout) {
        return new SessionOptions(transcriptFileBytes, keepDays, smtp, backoff, timeout, webhooks);
    }

    /** Lets webhooks reach these non-public ranges too ({@code --webhook-allow}). */
    public SessionOptions withWebhooks(WebhookTargets w) {
        return new SessionOptions(transcriptFileBytes, keepDays, smtp, notifyBackoff, notifyTimeout, w);
    }
}
