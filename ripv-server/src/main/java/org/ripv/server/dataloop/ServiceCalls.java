package org.ripv.server.dataloop;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import org.ripv.messages.Attachment;
import org.ripv.messages.Footer;

/**
 * Requests the server itself sends to services, on a user's behalf, with the answer coming back
 * here rather than to a client. They travel exactly like a client's (same forwarding, pending
 * timeout, SERVICE_GONE), with the server's client id {@code 000000}.
 */
public interface ServiceCalls {
    /** The full names ({@code <DatabaseServer>::<host>}) of the registered services with this SID, sorted. */
    List<String> services(String sid);

    /**
     * Why {@code user} may not have a file of the download directory ({@code FOLDER/NAME}), or null
     * when they may: the rule a command that names the file is held to ({@code DownloadRights}),
     * decided without reading the file.
     */
    String whyNotDownload(String user, String downloadName);

    /** Whether the permit file lets {@code user} send {@code body} to {@code mailbox}. */
    boolean permitted(String user, String mailbox, String body);

    /**
     * Sends {@code body} to {@code mailbox} as {@code user} (with {@code roles}). Download-directory
     * files are attached as for a client's command; {@code attachment}, when not null, instead.
     *
     * @param progress hears PROGRESS replies
     * @return the final footer: OK, or ERROR (also for timeouts and services that are gone)
     */
    CompletableFuture<Footer> call(String mailbox, String body, String user, List<String> roles, Attachment attachment,
                                   Consumer<Footer> progress);
}
