package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.util.List;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.Progress;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.TableResult;

/**
 * What the client's reply dispatch may do to the GUI (thesis 5.2.6, figure 5.5): the
 * {@link GuiManager} switches on a reply's Footer SID or FID and calls one of these, which
 * update the {@link ClientModel} on the event thread. Any thread may call them.
 *
 * <p>The mapping (Appendix B): {@code ?services} (777777) → {@link #showServices} (SEL tree and
 * tabs); {@code ?mailboxes} (555555) → {@link #showMailboxes} (MAM trees); {@code ?status}
 * (555666) → {@link #showMailboxStatus} (SS label); {@code ?uldir}/{@code ?dldir}
 * (444445/444444) → {@link #showDirectory}; {@code ?ulfiles}/{@code ?dlfiles} (444455/444454)
 * → {@link #showFiles} (FIM FileTree); DatabaseServer (666666) tables → {@link #showTable}
 * (DAB); DataVisServer (999999) images → {@link #showImage} (DAV); SerialPortServer (888888)
 * and every other service's text → {@link #showReply} (COM reply area), its PROGRESS →
 * {@link #showProgress}.
 */
public interface GuiInterface {

    /** The registered services: tabs and the SEL tree follow this list. */
    void showServices(List<ServiceDescriptor> services);

    /** Every registered service's MailBoxes; each MAM tree takes its own service's. */
    void showMailboxes(List<MailboxStatus> mailboxes);

    /** One MailBox's status (SS label when it is a target; its MAM node always). */
    void showMailboxStatus(MailboxStatus status);

    /** The path of the server's upload or download directory (FileTree root). */
    void showDirectory(FileArea area, String path);

    /** The files in the server's upload or download directory. */
    void showFiles(FileArea area, FileListing listing);

    /** Who the server says we are. */
    void showSession(SessionInfo session);

    /** A line for a service's COM reply area. */
    void showReply(String service, LineKind kind, String text);

    /** A service's command in progress, or null when it has finished. */
    void showProgress(String service, Progress progress);

    /** A query's table for the service's DAB panel (one new tab). */
    void showTable(String service, TableResult table);

    /** A plot for the service's DAV panel; {@code decoded} is null when the bytes are no image. */
    void showImage(String service, ImageResult image, BufferedImage decoded);

    /** A message for the window's status bar. */
    void showNotice(String text, boolean error);

    /** The connection's state and why. */
    void showConnection(Connection state, String detail);

    /**
     * Console entries of a watched MailBox ({@code ?watch} 555700 replay, pushes 555790);
     * {@code live} is false for the replay, so old events raise no desktop notification.
     */
    default void showConsole(ConsoleBatch batch, boolean live) {
    }

    /** Transcript entries ({@code ?history}, 555702) to put before a console's lines. */
    default void showHistory(ConsoleBatch batch) {
    }

    /** A request of a service tab was sent and runs until its final reply (COM shows it with Cancel). */
    default void requestStarted(String service, long messageId, String command) {
    }

    /** A PROGRESS reply for a running request. */
    default void requestProgress(String service, long messageId, Progress progress) {
    }

    /**
     * A running request ended: its final reply came ({@code code} null for OK, else the error's
     * code, e.g. {@code CANCELLED}), or it failed without one.
     */
    default void requestEnded(String service, long messageId, ErrorCode code) {
    }
}
