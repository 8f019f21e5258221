package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.net.URI;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** A raw TCP link: a vehicle, a ser2net-style port server, or the glider simulator. */
public final class TcpLink implements Link {
    private static final Logger log = LoggerFactory.getLogger(TcpLink.class);
    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final String description;
    private int soTimeout = -1;

    /** Wraps a connected socket (the simulator's side of a connection). */
    public TcpLink(Socket socket) throws IOException {
        this.socket = socket;
        socket.setTcpNoDelay(true); // YMODEM's one-byte ACKs must not wait for Nagle
        this.in = socket.getInputStream();
        this.out = socket.getOutputStream();
        this.description = "tcp://" + socket.getInetAddress().getHostAddress() + ":" + socket.getPort();
    }

    /** Connects to {@code tcp://host:port}. */
    public static TcpLink connect(String uri, int connectTimeoutMillis) throws IOException {
        URI u = URI.create(uri);
        if (!"tcp".equals(u.getScheme()) || u.getHost() == null || u.getPort() < 0) {
            throw new IllegalArgumentException("'" + uri + "' is not tcp://host:port");
        }
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(u.getHost(), u.getPort()), connectTimeoutMillis);
        } catch (IOException e) {
            s.close();
            throw e;
        }
        return new TcpLink(s);
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        int t = (int) Math.max(1, Math.min(Integer.MAX_VALUE, timeoutMillis));
        if (t != soTimeout) {
            socket.setSoTimeout(t);
            soTimeout = t;
        }
        try {
            int n = in.read(buffer, offset, len);
            if (n < 0) {
                throw new EOFException(description + " was closed by the other end");
            }
            return n;
        } catch (SocketTimeoutException e) {
            return 0;
        }
    }

    @Override
    public void write(byte[] buffer, int offset, int len) throws IOException {
        out.write(buffer, offset, len);
    }

    @Override
    public void flush() throws IOException {
        out.flush();
    }

    @Override
    public String describe() {
        return description;
    }

    @Override
    public boolean hasCarrierLine() {
        return false;
    }

    /** The kernel's socket buffers take megabytes; the modem at the far end drains them at its own rate. */
    @Override
    public boolean buffersDeeply() {
        return true;
    }

    @Override
    public boolean carrier() {
        return true;
    }

    @Override
    public void close() {
        try {
            out.flush();
            socket.close();
        } catch (IOException e) {
            log.debug("closing {}: {}", description, e.toString());
        }
    }
}
