package org.ripv.server.files;

import java.io.IOException;
import java.util.Optional;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.session.Rights;

/**
 * The one place that says whether a user may have a file of the download directory — fetched
 * with {@code ?download}, or attached to a command ({@code vis:file NAME}, {@code ingest NAME}).
 * A file in a MailBox's folder is that MailBox's data: it needs the read right ({@code ?read}) on
 * that MailBox, as its console and transcript do (issue 23, item 5: a user with rights on the
 * DataVisServer only attached another vehicle's download). Loose files, and folders not yet
 * claimed by a MailBox since the upgrade, need the {@code ?download} gate only.
 */
public final class DownloadRights {
    private DownloadRights() {}

    /**
     * Refuses a file the user may not have.
     *
     * @throws SecurityRefusal quoting the file, its MailBox and the rule that decided
     */
    public static void check(FileStore files, PermitFile permits, String user, String name) throws IOException {
        Optional<String> mailbox = files.mailboxOf(name);
        if (mailbox.isEmpty()) {
            return;
        }
        String why = Rights.whyNotRead(permits, user, mailbox.get());
        if (why != null) {
            throw new SecurityRefusal("'" + name + "' came from " + mailbox.get() + ", and " + why
                    + "; a download needs the ?read right on the MailBox it came from (docs/permit.md)");
        }
    }
}
