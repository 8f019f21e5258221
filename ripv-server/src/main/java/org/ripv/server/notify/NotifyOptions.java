package org.ripv.server.notify;

import java.io.IOException;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code ripv server}'s options for notifications (a picocli mixin): the SMTP server e-mail goes
 * through, and the non-public addresses webhooks may reach.
 */
public final class NotifyOptions {
    @Option(names = "--smtp", paramLabel = "HOST:PORT", description = "The SMTP server for e-mail notifications (?notify add email ...).")
    String smtp;

    @Option(names = "--smtp-credentials", paramLabel = "FILE", description = "Properties file with user=, password= (and from=, starttls=true) for --smtp.")
    Path smtpCredentials;

    @Option(names = "--webhook-allow", paramLabel = "CIDR[,CIDR...]",
            description = "Non-public addresses webhooks may reach too (e.g. 10.0.0.0/8, 127.0.0.1/32, or any); "
                    + "by default only public addresses (docs/sessions.md#notifications).")
    String webhookAllow;

    /** Where webhooks may go. */
    public WebhookTargets webhooks() {
        return WebhookTargets.parse(webhookAllow);
    }

    /**
     * The SMTP server, or null without {@code --smtp}.
     *
     * @throws IllegalArgumentException for a bad {@code --smtp}, or {@code --smtp-credentials} without it
     * @throws IOException              when the credentials file cannot be read
     */
    public Smtp smtp() throws IOException {
        if (smtp != null) {
            return Smtp.parse(smtp, smtpCredentials);
        }
        if (smtpCredentials != null) {
            throw new IllegalArgumentException("--smtp-credentials needs --smtp HOST:PORT");
        }
        return null;
    }
}
