package org.ripv.server;

import java.time.Duration;
import org.ripv.server.notify.Smtp;

/**
 * How the server keeps vehicle sessions (docs/sessions.md): transcript rotation and age, the
 * SMTP server for e-mail notifications, and notification retry timing.
 *
 * @param transcriptFileBytes a transcript file grows to about this size before the next starts
 * @param keepDays            transcript files of days older than this are deleted
 * @param smtp                the SMTP server for e-mail notifications, or null for none
 * @param notifyBackoff       the first retry's delay (later retries wait four times longer each)
 * @param notifyTimeout       how long a webhook or SMTP server may take to connect, and then to answer
 */
public record SessionOptions(long transcriptFileBytes, int keepDays, Smtp smtp, Duration notifyBackoff,
                             Duration notifyTimeout) {
    public static final long DEFAULT_FILE_BYTES = 64L * 1024 * 1024;
    public static final int DEFAULT_KEEP_DAYS = 90;

    public SessionOptions {
        if (transcriptFileBytes < 4096) {
            throw new IllegalArgumentException("a transcript file must be allowed at least 4096 bytes");
        }
        if (keepDays < 1) {
            throw new IllegalArgumentException("transcripts must be kept at least 1 day");
        }
    }

    public static SessionOptions defaults() {
        return new SessionOptions(DEFAULT_FILE_BYTES, DEFAULT_KEEP_DAYS, null, Duration.ofSeconds(5), Duration.ofSeconds(10));
    }

    public SessionOptions withSmtp(Smtp s) {
        return new SessionOptions(transcriptFileBytes, keepDays, s, notifyBackoff, notifyTimeout);
    }

    public SessionOptions withTranscripts(long fileBytes, int days) {
        return new SessionOptions(fileBytes, days, smtp, notifyBackoff, notifyTimeout);
    }

    public SessionOptions withNotifyTiming(Duration backoff, Duration timeout) {
        return new SessionOptions(transcriptFileBytes, keepDays, smtp, backoff, timeout);
    }
}
