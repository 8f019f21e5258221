package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One open link with the one thread that reads it, always: everything the vehicle prints goes to
 * the console ({@link Traffic#text}); while a command runs, it also goes to the command
 * ({@link #listen}), which reads it through this object as if it were the link. During a YMODEM
 * transfer ({@link #binary}) the bytes go to the command only, never to the console.
 */
final class Connection extends FilterLink {
    private static final Logger log = LoggerFactory.getLogger(Connection.class);
    /** How long a read waits before the reader looks at the clock (partial lines, quiet, carrier). */
    static final long TICK_MILLIS = 250;

    /** Where the reader reports. Called on the reader thread. */
    interface Traffic {
        /** Text the vehicle printed (not during a transfer). */
        void text(byte[] bytes, int length);

        /** Bytes of a transfer arrived: the vehicle is there, but this is no text. */
        void alive();

        /** Called at least every {@link #TICK_MILLIS} ms, output or not. */
        void tick(Connection connection);

        /** The link failed or the far end hung up ({@code e} says which); the reader has stopped. */
        void ended(Connection connection, IOException e);
    }

    private final Traffic traffic;
    private final boolean call;
    private final ReplyPipe pipe = new ReplyPipe(64 * 1024);
    private final Thread reader;
    private volatile boolean binary;
    private volatile boolean closed;

    /**
     * @param call true when this is a caller on a listen link (its end is the call's end)
     */
    Connection(Link link, Traffic traffic, String name, boolean call) {
        super(link);
        this.traffic = traffic;
        this.call = call;
        this.reader = new Thread(this::read, "serial-reader-" + name);
        reader.setDaemon(true);
    }

    Connection start() {
        reader.start();
        return this;
    }

    boolean isCall() {
        return call;
    }

    /** From now on, copies what the vehicle says for the running command, starting empty. */
    void listen() {
        pipe.open();
    }

    /** The command is done with the link's output. */
    void stopListening() {
        pipe.close();
    }

    /** A transfer is under way: the bytes are not console text. */
    void binary(boolean on) {
        binary = on;
    }

    private void read() {
        byte[] buf = new byte[4096];
        long lastTick = System.nanoTime();
        try {
            while (!closed) {
                int n = link.read(buf, 0, buf.length, TICK_MILLIS);
                if (n > 0) {
                    pipe.put(buf, 0, n);
                    if (binary) {
                        traffic.alive();
                    } else {
                        traffic.text(buf, n);
                    }
                }
                long now = System.nanoTime();
                if (n == 0 || now - lastTick > TimeUnit.MILLISECONDS.toNanos(TICK_MILLIS)) {
                    lastTick = now;
                    traffic.tick(this);
                }
            }
        } catch (IOException e) {
            pipe.fail(e);
            if (!closed) {
                traffic.ended(this, e);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            log.error("reader of {} failed", link.describe(), e);
            pipe.fail(new IOException("the link's reader failed: " + e));
            traffic.ended(this, new IOException("the link's reader failed: " + e, e));
        }
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        return pipe.read(buffer, offset, len, timeoutMillis);
    }

    /** Hangs up: closes the link and lets the reader end (without reporting it as a failure). */
    @Override
    public void close() {
        closed = true;
        link.close();
        pipe.fail(new EOFException(link.describe() + " was closed"));
        if (Thread.currentThread() != reader) {
            try {
                reader.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
