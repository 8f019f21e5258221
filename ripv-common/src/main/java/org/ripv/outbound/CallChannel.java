package org.ripv.outbound;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.net.Socket;
import java.rmi.RemoteException;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.ripv.wire.WireFilter;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link GenericRMIInterface} calls in both directions over one authenticated TCP connection.
 * Each frame is a length-prefixed object stream read through {@link WireFilter#forFrames}:
 * {@code {id, "call", method, args}}, {@code {id, "ok", value}} or
 * {@code {id, "err", kind, message}}. Calls to the other side go out through {@link #remote()},
 * a {@link Proxy} that behaves like an RMI stub (a failed or late call throws
 * {@link RemoteException}); calls from the other side run, in order, on one thread of this
 * channel against the local object. A call that gets no answer within the deadline closes the
 * channel — every RIPV call returns at once, so silence means the line is dead.
 */
public final class CallChannel implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(CallChannel.class);
    private static final Map<String, Method> METHODS = new HashMap<>();

    static {
        for (Method m : GenericRMIInterface.class.getMethods()) {
            METHODS.put(m.getName(), m);
        }
    }

    private final Socket socket;
    private final String peer;
    private final int maxFrame;
    private final WireFilter filter;
    private final Duration deadline;
    private final GenericRMIInterface local;
    private final DataInputStream in;
    private final DataOutputStream out;
    private final LinkedBlockingQueue<byte[]> outgoing = new LinkedBlockingQueue<>(10_000);
    private final Map<Long, CompletableFuture<Object>> calls = new ConcurrentHashMap<>();
    private final AtomicLong ids = new AtomicLong();
    private final ExecutorService incoming;
    private final CompletableFuture<String> closed = new CompletableFuture<>();
    private final GenericRMIInterface remote;

    /**
     * Starts serving a connection whose handshake is done.
     *
     * @param local    answers the other side's calls
     * @param deadline how long a call to the other side may wait for its answer
     */
    public CallChannel(Socket socket, String peer, GenericRMIInterface local, int maxFrame, Duration deadline) throws IOException {
        this.socket = socket;
        this.peer = peer;
        this.local = local;
        this.maxFrame = maxFrame;
        this.filter = WireFilter.forFrames(maxFrame);
        this.deadline = deadline;
        socket.setSoTimeout(0); // silence is judged by call deadlines, not by reads
        socket.setTcpNoDelay(true);
        socket.setKeepAlive(true);
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 65_536));
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream(), 65_536));
        this.incoming = Executors.newSingleThreadExecutor(r -> daemon(r, "ripv-outbound-calls-" + peer));
        this.remote = (GenericRMIInterface) Proxy.newProxyInstance(GenericRMIInterface.class.getClassLoader(),
                new Class<?>[] {GenericRMIInterface.class}, new Stub());
        daemon(this::readLoop, "ripv-outbound-reader-" + peer).start();
        daemon(this::writeLoop, "ripv-outbound-writer-" + peer).start();
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    /** The other side, as if it were an RMI stub. */
    public GenericRMIInterface remote() {
        return remote;
    }

    /** Completes with the reason when the connection ends. */
    public CompletableFuture<String> closed() {
        return closed;
    }

    public boolean isOpen() {
        return !closed.isDone();
    }

    /** Who is at the other end (HOST:PORT). */
    public String peer() {
        return peer;
    }

    @Override
    public void close() {
        close("closed");
    }

    private void close(String why) {
        if (!closed.complete(why)) {
            return;
        }
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        incoming.shutdownNow();
        RemoteException gone = new RemoteException("the outbound connection " + peer + " closed: " + why);
        calls.values().forEach(f -> f.completeExceptionally(gone));
        calls.clear();
        outgoing.offer(new byte[0]); // wakes the writer
        log.info("outbound connection {} closed: {}", peer, why);
    }

    private byte[] encode(Object[] frame) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(256);
        try (ObjectOutputStream o = new ObjectOutputStream(bytes)) {
            o.writeObject(frame);
        }
        if (bytes.size() > maxFrame) {
            throw new ProtocolException("a call of " + bytes.size() + " bytes is over the frame limit of " + maxFrame);
        }
        return bytes.toByteArray();
    }

    private Object[] decode(byte[] body) throws ProtocolException {
        try (ObjectInputStream o = new ObjectInputStream(new ByteArrayInputStream(body))) {
            o.setObjectInputFilter(filter);
            Object f = o.readObject();
            if (!(f instanceof Object[] a) || a.length < 3 || !(a[0] instanceof Long) || !(a[1] instanceof String)) {
                throw new ProtocolException("not a call frame");
            }
            return a;
        } catch (ProtocolException e) {
            throw e;
        } catch (Exception | StackOverflowError | OutOfMemoryError e) {
            throw new ProtocolException("rejected a malformed or disallowed frame: " + e, e);
        }
    }

    private void send(Object[] frame) throws IOException {
        if (!outgoing.offer(encode(frame))) {
            throw new IOException("too many frames waiting to go out to " + peer);
        }
    }

    private void writeLoop() {
        try {
            while (isOpen()) {
                byte[] body = outgoing.take();
                if (body.length == 0) {
                    break;
                }
                out.writeInt(body.length);
                out.write(body);
                if (outgoing.isEmpty()) {
                    out.flush();
                }
            }
        } catch (IOException e) {
            close("write failed: " + e.getMessage());
        } catch (InterruptedException e) {
            close("interrupted");
        }
    }

    private void readLoop() {
        try {
            while (isOpen()) {
                int length = in.readInt();
                if (length <= 0 || length > maxFrame) {
                    throw new ProtocolException("frame length " + length + " outside 1.." + maxFrame);
                }
                byte[] body = new byte[length];
                in.readFully(body);
                Object[] f = decode(body);
                long id = (Long) f[0];
                switch ((String) f[1]) {
                    case "call" -> incoming.execute(() -> answer(id, f));
                    case "ok" -> done(id, f[2], null);
                    case "err" -> done(id, null, failure(f));
                    default -> throw new ProtocolException("unknown frame kind " + f[1]);
                }
            }
        } catch (EOFException e) {
            close("the other side closed the connection");
        } catch (IOException e) {
            close(e.getMessage());
        } catch (RuntimeException e) {
            close("bad frame: " + e);
        }
    }

    private void done(long id, Object value, Exception error) {
        CompletableFuture<Object> f = calls.remove(id);
        if (f != null) {
            if (error == null) {
                f.complete(value);
            } else {
                f.completeExceptionally(error);
            }
        }
    }

    private static Exception failure(Object[] f) {
        String kind = f.length > 2 ? String.valueOf(f[2]) : "remote";
        String message = f.length > 3 ? String.valueOf(f[3]) : "";
        return switch (kind) {
            case "security" -> new SecurityException(message);
            case "unsupported" -> new UnsupportedOperationException(message);
            case "illegal-state" -> new IllegalStateException(message);
            case "illegal-argument" -> new IllegalArgumentException(message);
            default -> new RemoteException(message);
        };
    }

    /** Runs one call from the other side against the local object and sends its result. */
    private void answer(long id, Object[] f) {
        Object[] reply;
        try {
            if (f.length != 4 || !(f[2] instanceof String name) || !(f[3] instanceof Object[] args)) {
                throw new IllegalArgumentException("a call frame is {id, call, method, args}");
            }
            Method m = METHODS.get(name);
            if (m == null || m.getParameterCount() != args.length) {
                throw new IllegalArgumentException("no method " + name + " with " + args.length + " argument(s)");
            }
            reply = new Object[] {id, "ok", m.invoke(local, args)};
        } catch (InvocationTargetException e) {
            reply = error(id, e.getCause());
        } catch (Exception e) {
            reply = error(id, e);
        }
        try {
            send(reply);
        } catch (IOException e) {
            close("could not answer: " + e.getMessage());
        }
    }

    private static Object[] error(long id, Throwable t) {
        String kind = t instanceof SecurityException ? "security"
                : t instanceof UnsupportedOperationException ? "unsupported"
                : t instanceof IllegalStateException ? "illegal-state"
                : t instanceof IllegalArgumentException ? "illegal-argument" : "remote";
        return new Object[] {id, "err", kind, t.getMessage() == null ? t.toString() : t.getMessage()};
    }

    /** Calls to the other side. */
    private final class Stub implements InvocationHandler {
        @Override
        public Object invoke(Object proxy, Method method, Object[] args) throws Throwable {
            switch (method.getName()) {
                case "toString":
                    return "outbound " + peer;
                case "hashCode":
                    return System.identityHashCode(proxy);
                case "equals":
                    return proxy == args[0];
                default:
                    break;
            }
            if (!isOpen()) {
                throw new RemoteException("the outbound connection " + peer + " is closed: " + closed.getNow(""));
            }
            long id = ids.incrementAndGet();
            CompletableFuture<Object> f = new CompletableFuture<>();
            calls.put(id, f);
            try {
                send(new Object[] {id, "call", method.getName(), args == null ? new Object[0] : args.clone()});
                return f.get(deadline.toMillis(), TimeUnit.MILLISECONDS);
            } catch (TimeoutException e) {
                close("no answer to " + method.getName() + " within " + deadline.toMillis() + " ms");
                throw new RemoteException("no answer from " + peer + " within " + deadline.toMillis() + " ms");
            } catch (ExecutionException e) {
                throw e.getCause();
            } catch (IOException e) {
                throw new RemoteException("could not send to " + peer + ": " + e.getMessage(), e);
            } finally {
                calls.remove(id);
            }
        }
    }
}
