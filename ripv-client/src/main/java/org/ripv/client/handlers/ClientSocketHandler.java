package org.ripv.client.handlers;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import javax.net.SocketFactory;
import org.ripv.failover.ServerList;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The client's end of the socket to a RIPVServer (thesis 5.2.6, figure 5.5). Requests go out as
 * frames; a reader thread matches each reply to its request by message id and tells every
 * {@link Listener}, so the GUI can dispatch on the Footer's SID or FID.
 *
 * <pre>{@code
 * try (ClientSocketHandler c = ClientSocketHandler.connect("server.example.org", 4444)) {
 *     c.login("alice", password);
 *     OutgoingServerMessage r = c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(10), null);
 * }
 * }</pre>
 */
public final class ClientSocketHandler implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ClientSocketHandler.class);
    /** Files move in chunks of this size, so no frame is large. */
    public static final int CHUNK = 256 * 1024;

    /** Told of every reply and of the connection's end. Called on the reader thread. */
    public interface Listener {
        void onReply(OutgoingServerMessage reply);

        default void onDisconnected(Exception cause) {
        }

        /**
         * One page of a table arrived ({@link TablePages}); {@link #onReply} sees the whole table
         * with the final reply. For those who time the first rows (bench database) or show them early.
         */
        default void onPage(OutgoingServerMessage page) {
        }
    }

    private record Pending(CompletableFuture<OutgoingServerMessage> done, Consumer<OutgoingServerMessage> progress) {}

    private final Socket socket;
    private final DataOutputStream out;
    private final DataInputStream in;
    private final FrameCodec codec;
    private final Map<Long, Pending> pending = new ConcurrentHashMap<>();
    private final PageJoiner pages = new PageJoiner();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final AtomicLong ids = new AtomicLong();
    private final Thread reader;
    private final String server;
    private volatile SessionInfo session;
    private volatile boolean closed;

    private ClientSocketHandler(Socket socket, String server, int maxFrame) throws IOException {
        this.socket = socket;
        this.server = server;
        this.codec = new FrameCodec(maxFrame);
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream(), 64 * 1024));
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 64 * 1024));
        FrameCodec.writeGreeting(out);
        FrameCodec.readGreeting(in); // within the connect's deadline: a web server never answers it
        socket.setSoTimeout(0);
        this.reader = new Thread(this::readLoop, "ripv-client-reader-" + server);
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * Connects over TLS, trusting the server's certificate on first use ({@link Tls#trustOnFirstUse}
     * with {@link Tls#defaultKnownHosts}); a server whose certificate changed is refused.
     * A {@code host} of the form {@code host1[:port],host2[:port]} connects to whichever answers
     * ({@link Failover}; {@code port} is then the default port).
     */
    public static ClientSocketHandler connect(String host, int port) throws IOException {
        if (host.indexOf(',') >= 0) {
            Failover f = failover(host, port);
            return f.connect((h, p) -> connect(h, p,
                    Tls.trustOnFirstUse(h, p, Tls.defaultKnownHosts(), n -> log.warn("{}", n), f.servers()), Failover.CONNECT));
        }
        return connect(host, port, Tls.trustOnFirstUse(host, port, Tls.defaultKnownHosts(), n -> log.warn("{}", n)),
                Duration.ofSeconds(10));
    }

    /** Connects over plain TCP, to a server started with {@code --plain} (a test lab); a list as in {@link #connect(String, int)}. */
    public static ClientSocketHandler connectPlain(String host, int port) throws IOException {
        if (host.indexOf(',') >= 0) {
            return failover(host, port).connect((h, p) -> connect(h, p, SocketFactory.getDefault(), Failover.CONNECT));
        }
        return connect(host, port, SocketFactory.getDefault(), Duration.ofSeconds(10));
    }

    /** One Failover per list, so that reconnects start with the server that answered last. */
    private static final Map<String, Failover> FAILOVERS = new ConcurrentHashMap<>();

    private static Failover failover(String list, int defaultPort) {
        return FAILOVERS.computeIfAbsent(list + "|" + defaultPort,
                k -> new Failover(ServerList.parse(list, defaultPort), null));
    }

    /** Connects with the given socket factory (an {@code SSLSocketFactory} for TLS). */
    public static ClientSocketHandler connect(String host, int port, SocketFactory factory, Duration timeout)
            throws IOException {
        return Dial.open(host, port, factory, timeout, s -> new ClientSocketHandler(s, host + ":" + port,
                FrameCodec.DEFAULT_MAX_FRAME));
    }

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    /** "host:port" of the server. */
    public String server() {
        return server;
    }

    /** Who the server logged us in as, or null before {@link #login}. */
    public SessionInfo session() {
        return session;
    }

    public boolean isOpen() {
        return !closed && !socket.isClosed();
    }

    /** A fresh message id. */
    public long nextId() {
        return ids.incrementAndGet();
    }

    /**
     * Logs in. The password travels in the request's attachment (use TLS across untrusted networks).
     *
     * @throws RipvErrorException with the server's reason when refused
     */
    public SessionInfo login(String user, char[] password) throws IOException, RipvErrorException {
        byte[] pw = new String(password).getBytes(StandardCharsets.UTF_8);
        Header h = new Header(nextId(), new IdBadge("000000", user), List.of(), "", "",
                "?login " + user, Priority.URGENT, new Attachment("password", pw));
        OutgoingServerMessage r = await(send(h, null), Duration.ofSeconds(30));
        Arrays.fill(pw, (byte) 0);
        if (r.status() == Status.ERROR) {
            throw new RipvErrorException(r);
        }
        if (!(r.footer().result() instanceof SessionInfo s)) {
            throw new ProtocolException("the server answered ?login without session information");
        }
        session = s;
        return s;
    }

    /**
     * Sends a request; the future completes with its final (OK or ERROR) reply.
     *
     * @param progress told of each PROGRESS reply, or null
     */
    public CompletableFuture<OutgoingServerMessage> send(Header header, Consumer<OutgoingServerMessage> progress)
            throws IOException {
        if (closed) {
            throw new IOException("the connection to " + server + " is closed");
        }
        CompletableFuture<OutgoingServerMessage> f = new CompletableFuture<>();
        pending.put(header.messageId(), new Pending(f, progress));
        try {
            synchronized (out) {
                codec.write(out, new IncomingServerMessage(header));
            }
        } catch (IOException e) {
            pending.remove(header.messageId());
            throw e;
        }
        return f;
    }

    /** Sends a command to a mailbox (empty for {@code ?} commands) and returns the future final reply. */
    public CompletableFuture<OutgoingServerMessage> send(String mailbox, String body, Priority priority,
                                                          Consumer<OutgoingServerMessage> progress) throws IOException {
        return send(Header.request(nextId(), mailbox, body, priority), progress);
    }

    /** Sends and waits for the final reply, OK or ERROR (an ERROR is returned, not thrown). */
    public OutgoingServerMessage call(String mailbox, String body, Priority priority, Duration timeout,
                                      Consumer<OutgoingServerMessage> progress) throws IOException {
        return await(send(mailbox, body, priority, progress), timeout);
    }

    OutgoingServerMessage await(CompletableFuture<OutgoingServerMessage> f, Duration timeout) throws IOException {
        try {
            return f.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for the server");
        } catch (TimeoutException e) {
            throw new IOException("no reply from " + server + " within " + timeout.toSeconds() + " s");
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
        }
    }

    /**
     * Uploads a local file to the server's upload directory, in chunks. The server writes to a
     * temporary file and moves it into place only when the last chunk arrived.
     *
     * @return the server's final reply to the last chunk
     * @throws RipvErrorException when the server refuses (name, size, permission)
     */
    public OutgoingServerMessage upload(Path local, String remoteName, TransferListener listener)
            throws IOException, RipvErrorException {
        return upload(local, remoteName, IfExists.ASK, listener);
    }

    /** What an upload does when the store has a file of that name ({@code ErrorCode.FILE_EXISTS} otherwise). */
    public enum IfExists {
        /** Send no choice: the server refuses with FILE_EXISTS, and the user is asked. */
        ASK(""),
        /** Replace the stored file (the server checks the right to). */
        REPLACE(" replace"),
        /** Keep both: the server stores this one under a new free name and says which. */
        KEEP(" keep");

        final String word;

        IfExists(String word) {
            this.word = word;
        }
    }

    /**
     * As {@link #upload(Path, String, TransferListener)}, saying what to do when the name is
     * taken ({@code ?upload NAME OFFSET TOTAL [replace|keep]}).
     */
    public OutgoingServerMessage upload(Path local, String remoteName, IfExists ifExists, TransferListener listener)
            throws IOException, RipvErrorException {
        return upload(local, remoteName, ifExists.word.strip(), listener);
    }

    /**
     * Uploads as {@link #upload(Path, String, TransferListener)} does, saying what to do when the
     * name is taken: null or empty refuses (FILE_EXISTS), {@code replace} replaces (a permit right),
     * {@code keep} stores under a new free name, which the last reply names.
     */
    public OutgoingServerMessage upload(Path local, String remoteName, String mode, TransferListener listener)
            throws IOException, RipvErrorException {
        return FileChunks.upload(this, local, remoteName, mode, listener);
    }

    /**
     * Downloads a file from the server's download directory into {@code localDir}, in chunks,
     * through a temporary file so that an interrupted download never looks complete.
     */
    public Path download(String name, Path localDir, TransferListener listener) throws IOException, RipvErrorException {
        return FileChunks.download(this, name, localDir, listener);
    }

    private void readLoop() {
        Exception cause = null;
        try {
            while (!closed) {
                Message m = codec.read(in);
                if (!(m instanceof OutgoingServerMessage reply)) {
                    throw new ProtocolException("the server sent a " + m.getClass().getSimpleName());
                }
                dispatch(reply);
            }
        } catch (EOFException e) {
            cause = new IOException("the server closed the connection");
        } catch (IOException e) {
            cause = e;
        } catch (RuntimeException e) {
            log.error("reply dispatch failed", e);
            cause = e;
        } finally {
            disconnected(cause);
        }
    }

    private void dispatch(OutgoingServerMessage reply) {
        long id = reply.header().messageId();
        if (TablePages.isPage(reply.footer())) {
            // A query's rows in pages: kept here, so that listeners and callers see one table, as before
            // (only for a request of ours: a page for anything else is dropped).
            if (pending.containsKey(id)) {
                pages.add(reply);
                for (Listener l : listeners) {
                    try {
                        l.onPage(reply);
                    } catch (RuntimeException e) {
                        log.warn("a listener failed on a page of #{}", id, e);
                    }
                }
            }
            return;
        }
        if (reply.status().isFinal()) {
            reply = pages.joined(reply);
        }
        // Listeners first: whoever waits on the future then finds them up to date.
        for (Listener l : listeners) {
            try {
                l.onReply(reply);
            } catch (RuntimeException e) {
                log.warn("a listener failed on {}", reply, e);
            }
        }
        Pending p = reply.status().isFinal() ? pending.remove(id) : pending.get(id);
        if (p != null) {
            if (reply.status().isFinal()) {
                p.done().complete(reply);
            } else if (p.progress() != null) {
                p.progress().accept(reply);
            }
        }
    }

    private void disconnected(Exception cause) {
        boolean wasClosed = closed;
        closed = true;
        IOException failure = new IOException(cause == null ? "connection closed" : cause.getMessage(), cause);
        pending.values().forEach(p -> p.done().completeExceptionally(failure));
        pending.clear();
        pages.clear();
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        if (!wasClosed) {
            for (Listener l : listeners) {
                try {
                    l.onDisconnected(failure);
                } catch (RuntimeException e) {
                    log.warn("a listener failed on disconnect", e);
                }
            }
        }
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            try {
                socket.close();
            } catch (IOException ignored) {
                // nothing left to do
            }
        }
    }
}
