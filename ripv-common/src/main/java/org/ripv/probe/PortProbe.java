package org.ripv.probe;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.cert.X509Certificate;
import java.time.Duration;
import java.util.Arrays;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;
import javax.net.ssl.SSLSocketFactory;
import javax.net.ssl.TrustManager;
import javax.net.ssl.X509TrustManager;
import org.ripv.wire.FrameCodec;

/**
 * Finds out what listens on a host's port by speaking to it the way each of RIPV's servers
 * answers: a Java RMI registry acknowledges JRMP's greeting, a web server answers {@code GET}
 * with {@code HTTP/}, RIPV's client port answers the RIPV greeting; each in the clear and over
 * TLS. It only runs after a connection went wrong, to explain it. Every step has its own
 * deadline, so the whole takes at most five of them.
 */
public final class PortProbe {
    /** What answered. */
    public enum Finding {
        NOTHING("nothing listens there (connection refused)"),
        SILENT("something there accepts connections but answers nothing RIPV knows"),
        RMI_REGISTRY("the Java RMI registry (RIPV's registry port, where services register)"),
        HTTP("a web server (RIPV's landing page port)"),
        RIPV_CLIENT_PORT("RIPV's client port (where the CLI and the GUI log in)"),
        RIPV_CLIENT_PORT_PLAIN("RIPV's client port, without TLS (a server started with --plain)");

        private final String what;

        Finding(String what) {
            this.what = what;
        }

        /** The words for an error message: "the Java RMI registry (...)". */
        public String what() {
            return what;
        }
    }

    private static final byte[] JRMP = {'J', 'R', 'M', 'I', 0, 2, 0x4b}; // magic, version 2, StreamProtocol
    private static final int JRMP_ACK = 0x4e;
    private static final byte[] GET = "GET / HTTP/1.0\r\n\r\n".getBytes(StandardCharsets.US_ASCII);
    /** The greeting a client of this version sends: a server refuses another version without a word. */
    static final byte[] GREETING = ByteBuffer.allocate(FrameCodec.MAGIC.length + Integer.BYTES).put(FrameCodec.MAGIC)
            .putInt(FrameCodec.VERSION).array();

    private PortProbe() {
    }

    /** What listens on {@code host:port}; each step waits at most {@code step}. */
    public static Finding identify(String host, int port, Duration step) {
        byte[] jrmp;
        try {
            jrmp = ask(host, port, false, JRMP, step);
        } catch (ConnectException e) {
            return Finding.NOTHING;
        } catch (IOException e) {
            jrmp = new byte[0];
        }
        if (jrmp.length > 0 && (jrmp[0] & 0xff) == JRMP_ACK) {
            return Finding.RMI_REGISTRY;
        }
        if (startsWith(quietly(host, port, true, GET, step), "HTTP/") || startsWith(quietly(host, port, false, GET, step), "HTTP/")) {
            return Finding.HTTP;
        }
        if (startsWith(quietly(host, port, true, GREETING, step), "RIPV")) {
            return Finding.RIPV_CLIENT_PORT;
        }
        if (startsWith(quietly(host, port, false, GREETING, step), "RIPV")) {
            return Finding.RIPV_CLIENT_PORT_PLAIN;
        }
        return Finding.SILENT;
    }

    private static byte[] quietly(String host, int port, boolean tls, byte[] said, Duration step) {
        try {
            return ask(host, port, tls, said, step);
        } catch (IOException e) {
            return new byte[0];
        }
    }

    /** Connects (over TLS if asked), says {@code said}, and returns the first bytes of the answer (none on EOF). */
    private static byte[] ask(String host, int port, boolean tls, byte[] said, Duration step) throws IOException {
        int millis = (int) Math.max(1, step.toMillis());
        try (Socket plain = new Socket()) {
            plain.connect(new InetSocketAddress(host, port), millis);
            plain.setSoTimeout(millis);
            Socket s = tls ? anyCertificate().createSocket(plain, host, port, true) : plain;
            try {
                if (s instanceof SSLSocket t) {
                    t.startHandshake();
                }
                OutputStream out = s.getOutputStream();
                out.write(said);
                out.flush();
                InputStream in = s.getInputStream();
                byte[] b = new byte[5];
                int n = 0;
                while (n < b.length) {
                    int r = in.read(b, n, b.length - n);
                    if (r < 0) {
                        break;
                    }
                    n += r;
                }
                return Arrays.copyOf(b, n);
            } catch (SocketTimeoutException e) {
                return new byte[0];
            } finally {
                s.close();
            }
        }
    }

    private static boolean startsWith(byte[] b, String prefix) {
        return new String(b, StandardCharsets.ISO_8859_1).startsWith(prefix);
    }

    /**
     * A TLS context that accepts any certificate: the probe only asks what kind of server this
     * is and sends nothing secret (a GET of / and the RIPV greeting), so there is nothing to
     * protect; the real connection checks the certificate as before.
     */
    private static SSLSocketFactory anyCertificate() throws IOException {
        try {
            SSLContext c = SSLContext.getInstance("TLS");
            c.init(null, new TrustManager[] {new X509TrustManager() {
                @Override
                public void checkClientTrusted(X509Certificate[] chain, String authType) {
                }

                @Override
                public void checkServerTrusted(X509Certificate[] chain, String authType) {
                }

                @Override
                public X509Certificate[] getAcceptedIssuers() {
                    return new X509Certificate[0];
                }
            }}, null);
            return c.getSocketFactory();
        } catch (GeneralSecurityException e) {
            throw new IOException("no TLS here: " + e.getMessage(), e);
        }
    }
}
