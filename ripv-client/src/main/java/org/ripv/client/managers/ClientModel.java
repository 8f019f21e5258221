package org.ripv.client.managers;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.ripv.messages.FileListing;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.SessionInfo;

/**
 * Everything the RIPVClient window shows, as plain data: the connection, the registered
 * services (SEL tree and tabs) with a {@link ServiceModel} each, the server's upload and
 * download directories (FIM FileTree), the client's own file transfers, and the latest notice.
 *
 * <p>Threading: the model is confined to one thread — the Swing event thread in the GUI, the
 * test thread in headless tests. {@link GuiManager} applies every change through its UI
 * executor and then tells the {@link Listener}s, which repaint.
 */
public final class ClientModel {

    /** The state of the link to the server. */
    public enum Connection { DISCONNECTED, CONNECTING, CONNECTED, LOST }

    /** The server's two file areas (FIM). */
    public enum FileArea {
        UPLOAD("Uploaded [UL]"), DOWNLOAD("Downloaded [DL]");

        private final String label;

        FileArea(String label) {
            this.label = label;
        }

        /** The FileTree's root node label. */
        public String label() {
            return label;
        }
    }

    /** What changed, so listeners repaint only their part. {@code service} is null for global changes. */
    public enum Kind { CONNECTION, SERVICES, MAILBOXES, COM, TABLES, IMAGE, FILES, TRANSFERS, NOTICE }

    /** A change notification. */
    public record Change(Kind kind, String service) {}

    /** Told of every change, on the model's thread. */
    @FunctionalInterface
    public interface Listener {
        void changed(Change change);
    }

    /** One directory of the server with its files, as far as known. */
    public record Directory(String path, List<FileListing.Entry> files) {
        public Directory {
            path = path == null ? "" : path;
            files = files == null ? List.of() : List.copyOf(files);
        }
    }

    private Connection connection = Connection.DISCONNECTED;
    private String connectionDetail = "";
    private String server = "";
    private SessionInfo session;
    private final Map<String, ServiceModel> services = new LinkedHashMap<>();
    private final Map<FileArea, Directory> directories = new LinkedHashMap<>();
    private final List<Transfer> transfers = new ArrayList<>();
    private String notice = "";
    private boolean noticeIsError;
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final ConsoleModel console = new ConsoleModel();
    private final WorkflowModel workflows = new WorkflowModel();

    private String opening = "";

    /**
     * The service the window opens on: the first with a vehicle MailBox (a SerialPortServer, or
     * any MailBox with a call state), chosen once when the MailBoxes are first known; empty before.
     * The window shows it once and leaves the choice to the user after that.
     */
    public String opening() {
        return opening;
    }

    /** Chooses the service to open on, once; true when this call chose it. */
    boolean openOn(String service) {
        if (!opening.isEmpty() || service == null || service.isEmpty()) {
            return false;
        }
        opening = service;
        return true;
    }

    /** The workflow queues and receipts looked at. */
    public WorkflowModel workflows() {
        return workflows;
    }

    /** The live consoles of watched MailBoxes. */
    public ConsoleModel console() {
        return console;
    }

    public ClientModel() {
        directories.put(FileArea.UPLOAD, new Directory("", List.of()));
        directories.put(FileArea.DOWNLOAD, new Directory("", List.of()));
    }

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    public Connection connection() {
        return connection;
    }

    /** Why the connection is in its state: the server's reason, the socket's error. */
    public String connectionDetail() {
        return connectionDetail;
    }

    /** "host:port" of the server, once known. */
    public String server() {
        return server;
    }

    /** Who the server logged us in as, or null. */
    public SessionInfo session() {
        return session;
    }

    /** The registered services in the order they were first seen. */
    public Collection<ServiceModel> services() {
        return Collections.unmodifiableCollection(services.values());
    }

    public List<String> serviceNames() {
        return List.copyOf(services.keySet());
    }

    /** The service's model, or null when it is not registered (any more). */
    public ServiceModel service(String name) {
        return services.get(name);
    }

    public Directory directory(FileArea area) {
        return directories.get(area);
    }

    public List<Transfer> transfers() {
        return Collections.unmodifiableList(transfers);
    }

    /**
     * The latest message for the status bar, one line: a message of several lines shows its first
     * with " …" ({@link #noticeDetail()} has it all).
     */
    public String notice() {
        int nl = notice.indexOf('\n');
        return nl < 0 ? notice : notice.substring(0, nl).stripTrailing() + " …";
    }

    /** The latest message in full (the status bar's tooltip). */
    public String noticeDetail() {
        return notice;
    }

    public boolean noticeIsError() {
        return noticeIsError;
    }

    // Mutators: GuiManager only, on the model's thread.

    void connection(Connection c, String detail, String serverAddress) {
        connection = c;
        connectionDetail = detail == null ? "" : detail;
        if (serverAddress != null) {
            server = serverAddress;
        }
        fire(Kind.CONNECTION, null);
    }

    void session(SessionInfo s) {
        session = s;
        fire(Kind.CONNECTION, null);
    }

    /**
     * Replaces the service list: services that vanished are dropped, new ones added, and the
     * ones that stayed keep their transcript, tables and picture.
     *
     * @return true when a service was added
     */
    boolean services(List<ServiceDescriptor> list) {
        Map<String, ServiceDescriptor> fresh = new LinkedHashMap<>();
        for (ServiceDescriptor d : list) {
            fresh.put(d.name(), d);
        }
        boolean changed = services.keySet().retainAll(fresh.keySet());
        boolean added = false;
        for (ServiceDescriptor d : fresh.values()) {
            ServiceModel m = services.get(d.name());
            if (m == null) {
                services.put(d.name(), new ServiceModel(d));
                changed = true;
                added = true;
            } else if (!m.descriptor().equals(d)) {
                m.descriptor(d);
                changed = true;
            }
        }
        if (changed) {
            fire(Kind.SERVICES, null);
        }
        return added;
    }

    void directory(FileArea area, String path) {
        Directory old = directories.get(area);
        directories.put(area, new Directory(path, old.files()));
        fire(Kind.FILES, null);
    }

    void files(FileArea area, FileListing listing) {
        Directory old = directories.get(area);
        String path = listing.directory().isBlank() ? old.path() : listing.directory();
        directories.put(area, new Directory(path, listing.files()));
        fire(Kind.FILES, null);
    }

    void addTransfer(Transfer t) {
        transfers.add(t);
        fire(Kind.TRANSFERS, null);
    }

    void transferChanged(Transfer t) {
        fire(Kind.TRANSFERS, null);
    }

    /** Forgets finished transfers. */
    void clearFinishedTransfers() {
        transfers.removeIf(Transfer::finished);
        fire(Kind.TRANSFERS, null);
    }

    void notice(String text, boolean error) {
        notice = text == null ? "" : text.strip();
        noticeIsError = error;
        fire(Kind.NOTICE, null);
    }

    void fire(Kind kind, String service) {
        Change c = new Change(kind, service);
        for (Listener l : listeners) {
            l.changed(c);
        }
    }
}
