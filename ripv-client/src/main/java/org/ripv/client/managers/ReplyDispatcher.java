package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.Requests.Origin;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Owns reply dispatch: each reply goes by its Footer's SID or FID (Appendix B) to the GuiInterface call that shows it. */
final class ReplyDispatcher {
    // Logs under the façade's name, as before the split.
    private static final Logger log = LoggerFactory.getLogger(GuiManager.class);

    private final GuiInterface gui;
    private final Requests requests;

    ReplyDispatcher(GuiInterface gui, Requests requests) {
        this.gui = gui;
        this.requests = requests;
    }

    /** See {@link GuiManager#dispatch}; any thread. */
    void dispatch(OutgoingServerMessage reply) {
        Footer f = reply.footer();
        Header h = reply.header();
        if (requests.quiet(h.messageId(), f.status().isFinal())) {
            return; // asked by a view for itself (GuiManager.ask): the future has it
        }
        Origin origin = requests.origin(h.messageId(), f.status().isFinal());
        String originService = origin == null ? null : origin.service();
        boolean echo = origin != null && origin.echo();
        Result result = f.result();
        if (originService != null && echo && !h.isServerCommand() && f.status().isFinal()) {
            gui.requestEnded(originService, h.messageId(), f.status() == Status.ERROR ? f.errorCode() : null);
        }
        if (f.status() == Status.ERROR) {
            error(reply, origin);
            if (h.isServerCommand()) {
                gui.showProgress(serviceOf(h, originService), null);
            } else {
                afterServiceReply(reply, originService);
            }
            return;
        }
        switch (f.serviceId()) {
            case Ids.FID_SERVICES -> {
                if (result instanceof ServiceList list) {
                    gui.showServices(list.services());
                }
            }
            case Ids.FID_MAILBOXES -> {
                if (result instanceof MailboxList list) {
                    gui.showMailboxes(list.mailboxes());
                }
            }
            case Ids.FID_STATUS -> {
                if (result instanceof MailboxStatus s) {
                    gui.showMailboxStatus(s);
                }
            }
            case Ids.FID_LOCK, Ids.FID_UNLOCK -> {
                if (result instanceof MailboxStatus s) {
                    gui.showMailboxStatus(s);
                } else {
                    // The lock changed: ask for the MailBox's status so SS and the MAM node show it.
                    String[] w = h.body().strip().split("\\s+");
                    if (w.length >= 2) {
                        requests.send("", "?status " + w[1], Priority.NORMAL, new Origin(originService, false));
                    }
                }
            }
            case Ids.FID_ULDIR -> gui.showDirectory(FileArea.UPLOAD, f.replyText().strip());
            case Ids.FID_DLDIR -> gui.showDirectory(FileArea.DOWNLOAD, f.replyText().strip());
            case Ids.FID_ULFILES -> {
                if (result instanceof FileListing l) {
                    gui.showFiles(FileArea.UPLOAD, l);
                }
            }
            case Ids.FID_DLFILES -> {
                if (result instanceof FileListing l) {
                    gui.showFiles(FileArea.DOWNLOAD, l);
                }
            }
            case Ids.FID_LOGIN, Ids.FID_WHOAMI -> {
                if (result instanceof SessionInfo s) {
                    gui.showSession(s);
                }
            }
            case Ids.FID_HISTORY -> {
                if (result instanceof ConsoleBatch b && origin == null) {
                    gui.showHistory(b); // the console panel's Older button (typed ?history stays in COM)
                    return;
                }
            }
            case Ids.FID_CONSOLE, Ids.FID_WATCH -> {
                if (result instanceof ConsoleBatch b) {
                    gui.showConsole(b, f.serviceId().equals(Ids.FID_CONSOLE));
                }
                if (!echo) {
                    return;
                }
            }
            case Ids.FID_UPLOAD, Ids.FID_DOWNLOAD -> {
                // Chunks of the client's own transfers: their progress goes through the Transfer.
                return;
            }
            case Ids.SID_DATABASE -> {
                database(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            case Ids.SID_DATAVIS -> {
                datavis(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            case Ids.SID_SERIAL -> {
                serial(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            default -> {
                if (!h.isServerCommand()) {
                    other(reply, serviceOf(h, originService));
                    afterServiceReply(reply, originService);
                    return;
                }
            }
        }
        // A server command typed in a COM panel: its text goes to that panel too.
        if (echo && f.status().isFinal()) {
            gui.showReply(originService, LineKind.REPLY, serverText(reply));
        }
    }

    /**
     * After a service's final reply: the progress bar goes, and the MailBox's status is asked
     * again, since a command may have changed it (GO submerges a glider, a plot counts).
     */
    private void afterServiceReply(OutgoingServerMessage reply, String originService) {
        if (!reply.status().isFinal()) {
            return;
        }
        String service = serviceOf(reply.header(), originService);
        gui.showProgress(service, null);
        String mailbox = reply.header().mailboxAddress();
        if (!mailbox.isBlank() && service != null) {
            requests.send("", "?status " + mailbox, Priority.NORMAL, new Origin(service, false));
        }
    }

    private void error(OutgoingServerMessage reply, Origin origin) {
        Footer f = reply.footer();
        String text = f.replyText().isBlank() ? "the server answered ERROR without a reason" : f.replyText();
        String full = text + " [" + f.errorCode() + " " + f.errorCode().number() + "]";
        String service = serviceOf(reply.header(), origin == null ? null : origin.service());
        log.info("error reply to '{}': {}", reply.header().body(), full);
        if (service != null && f.errorCode() == ErrorCode.CANCELLED) {
            // Not a failure: someone stopped it on purpose, and the line says who.
            gui.showReply(service, LineKind.NOTICE, "cancelled '" + reply.header().body() + "': " + text);
        } else if (service != null) {
            gui.showReply(service, LineKind.ERROR, full);
        } else {
            // A background request (refresh, status): the status bar is where it shows.
            gui.showNotice("'" + reply.header().body() + "': " + full, true);
        }
    }

    private void database(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.result() instanceof TableResult t) {
            gui.showTable(service, t);
            gui.showReply(service, LineKind.REPLY, f.replyText().isBlank()
                    ? t.rows().size() + " row(s)" + (t.truncated() ? ", truncated" : "") : f.replyText());
        } else if (f.result() instanceof UpdateCount u) {
            gui.showReply(service, LineKind.REPLY,
                    f.replyText().isBlank() ? u.count() + " row(s) changed" : f.replyText());
        } else {
            other(reply, service);
        }
    }

    private void datavis(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.result() instanceof ImageResult img) {
            BufferedImage decoded = decode(img);
            gui.showImage(service, img, decoded);
            gui.showReply(service, LineKind.REPLY, f.replyText().isBlank() ? "plot " + img.name() : f.replyText());
            // The server stored the JPEG in its download directory as well.
            requests.background("?dlfiles");
        } else {
            other(reply, service);
        }
    }

    private void serial(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.status() == Status.PROGRESS) {
            other(reply, service);
            return;
        }
        gui.showProgress(service, null);
        if (f.result() instanceof FileListing l) {
            // After ymodem:get the server stored the files and lists what it stored.
            StringBuilder b = new StringBuilder(f.replyText().isBlank() ? "stored in the download directory:" : f.replyText());
            for (FileListing.Entry e : l.files()) {
                b.append("\n  ").append(e.name()).append("  ").append(e.size()).append(" bytes");
            }
            gui.showReply(service, LineKind.REPLY, b.toString());
            requests.background("?dlfiles");
        } else {
            gui.showReply(service, LineKind.REPLY, f.replyText());
        }
    }

    /** Any service's reply, by its result's type (new services work without GUI changes). */
    private void other(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        Result result = f.result();
        if (f.status() == Status.PROGRESS) {
            if (result instanceof Progress p) {
                gui.showProgress(service, p);
                gui.requestProgress(service, reply.header().messageId(), p);
            }
            if (!f.replyText().isBlank() && !(result instanceof Progress)) {
                gui.showReply(service, LineKind.PROGRESS, f.replyText());
            }
            return;
        }
        gui.showProgress(service, null);
        if (result instanceof TableResult t) {
            gui.showTable(service, t);
        } else if (result instanceof ImageResult img) {
            gui.showImage(service, img, decode(img));
        }
        gui.showReply(service, LineKind.REPLY, f.replyText().isBlank() && result != null
                ? result.getClass().getSimpleName() : f.replyText());
    }

    private static String serverText(OutgoingServerMessage reply) {
        Footer f = reply.footer();
        StringBuilder b = new StringBuilder(f.replyText());
        if (f.result() instanceof FileListing l && !f.replyText().contains("\n")) {
            for (FileListing.Entry e : l.files()) {
                b.append("\n  ").append(e.name()).append("  ").append(e.size()).append(" bytes");
            }
        } else if (f.result() instanceof ServiceList l && f.replyText().isBlank()) {
            l.services().forEach(d -> b.append(d.name()).append("  ").append(d.description()).append('\n'));
        } else if (f.result() instanceof MailboxList l && f.replyText().isBlank()) {
            l.mailboxes().forEach(m -> b.append(m.address()).append("  ").append(ServiceModel.describe(m)).append('\n'));
        } else if (f.result() instanceof MailboxStatus s && f.replyText().isBlank()) {
            b.append(s.address()).append("  ").append(ServiceModel.describe(s));
        }
        return b.length() == 0 ? "OK" : b.toString();
    }

    /** The service a reply belongs to: its destination, its mailbox's service, or where it was sent from. */
    static String serviceOf(Header h, String fallback) {
        if (!h.serviceDestination().isBlank()) {
            return h.serviceDestination();
        }
        if (!h.mailboxAddress().isBlank()) {
            try {
                return MailboxAddress.parse(h.mailboxAddress()).service().toString();
            } catch (MalformedNameException e) {
                return fallback;
            }
        }
        return fallback;
    }

    private static BufferedImage decode(ImageResult img) {
        try {
            return ImageIO.read(new ByteArrayInputStream(img.jpeg()));
        } catch (IOException | RuntimeException e) {
            log.warn("{} does not decode as an image: {}", img.name(), e.toString());
            return null;
        }
    }
}
