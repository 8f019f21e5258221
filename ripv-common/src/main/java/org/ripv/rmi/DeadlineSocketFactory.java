package org.ripv.rmi;

import java.io.IOException;
import java.io.Serializable;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.rmi.server.RMIClientSocketFactory;

/**
 * The client sockets RMI opens to call a RIPV process, with a connect deadline and a read deadline.
 * Plain RMI connects with no deadline at all, so a call to a host behind a firewall that drops
 * packets waits for the kernel's SYN retries (over two minutes). A RIPV process exports its
 * remote object with this factory; RMI serializes it into the stub, so whoever calls that object
 * connects through it.
 *
 * <p>The exporting side chooses the deadlines; the calling side may lower them with the system
 * properties {@value #CONNECT_PROPERTY} and {@value #READ_PROPERTY} (milliseconds), so that a
 * server never waits longer than its own settings on any service.
 *
 * @param connectMillis how long a TCP connect may take
 * @param readMillis    how long a call may wait for bytes of its reply (0: no read deadline)
 */
public record DeadlineSocketFactory(int connectMillis, int readMillis) implements RMIClientSocketFactory, Serializable {
    private static final long serialVersionUID = 1L;
    /** Caps the connect deadline of every stub this process calls. */
    public static final String CONNECT_PROPERTY = "ripv.rmi.connectTimeout";
    /** Caps the read deadline of every stub this process calls. */
    public static final String READ_PROPERTY = "ripv.rmi.readTimeout";
    /** A few seconds: a host on a working network answers a connect in milliseconds. */
    public static final int DEFAULT_CONNECT_MILLIS = 3_000;
    /** Every RIPV call returns at once (requests are queued, not run), so 15 s is generous. */
    public static final int DEFAULT_READ_MILLIS = 15_000;

    public DeadlineSocketFactory {
        if (connectMillis <= 0 || readMillis < 0) {
            throw new IllegalArgumentException("deadlines must be positive: connect " + connectMillis + " ms, read " + readMillis + " ms");
        }
    }

    /** The factory with this process's settings (the properties above, else the defaults). */
    public static DeadlineSocketFactory fromSystem() {
        return new DeadlineSocketFactory(property(CONNECT_PROPERTY, DEFAULT_CONNECT_MILLIS),
                property(READ_PROPERTY, DEFAULT_READ_MILLIS));
    }

    @Override
    public Socket createSocket(String host, int port) throws IOException {
        int connect = Math.min(connectMillis, property(CONNECT_PROPERTY, connectMillis));
        int read = readMillis == 0 ? property(READ_PROPERTY, 0) : Math.min(readMillis, property(READ_PROPERTY, readMillis));
        Socket s = new Socket();
        try {
            s.setTcpNoDelay(true);
            s.setKeepAlive(true);
            s.connect(new InetSocketAddress(host, port), connect);
            s.setSoTimeout(read);
            return s;
        } catch (SocketTimeoutException e) {
            s.close();
            throw new SocketTimeoutException("could not reach " + host + ":" + port + ": timed out after " + connect + " ms");
        } catch (IOException e) {
            s.close();
            throw e;
        }
    }

    private static int property(String key, int fallback) {
        String v = System.getProperty(key);
        if (v == null || v.isBlank()) {
            return fallback;
        }
        try {
            int n = Integer.parseInt(v.trim());
            return n > 0 ? n : fallback;
        } catch (NumberFormatException e) {
            return fallback;
        }
    }
}
