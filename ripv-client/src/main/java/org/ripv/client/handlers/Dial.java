package org.ripv.client.handlers;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import javax.net.SocketFactory;
import javax.net.ssl.SSLException;
import javax.net.ssl.SSLParameters;
import javax.net.ssl.SSLSocket;

/**
 * Opens the socket to a RIPVServer: connect within the deadline, and for TLS the host name
 * checked against the certificate and the handshake run at once, so that a refused or changed
 * certificate, or nothing listening, is said in plain words before any frame is sent.
 */
final class Dial {
    private Dial() {}

    /** What is made of the open socket: the connection, once the greetings are exchanged. */
    @FunctionalInterface
    interface Greeting<T> {
        T greet(Socket socket) throws IOException;
    }

    /**
     * Connects (TLS: with the handshake), sets the read deadline for the greeting and hands the
     * socket to {@code greeting}; a failure on the way closes the socket and says what answered
     * on that port ({@link WrongPort}).
     */
    static <T> T open(String host, int port, SocketFactory factory, Duration timeout, Greeting<T> greeting) throws IOException {
        Socket s = factory.createSocket();
        if (s instanceof SSLSocket tls) {
            // Check that the certificate names the host we asked for, not only that a CA signed it.
            SSLParameters p = tls.getSSLParameters();
            p.setEndpointIdentificationAlgorithm("HTTPS");
            tls.setSSLParameters(p);
        }
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(host, port), (int) timeout.toMillis());
        } catch (ConnectException e) {
            s.close();
            throw new IOException("nothing listens on " + host + ":" + port + " (" + e.getMessage()
                    + "): is the server running, and is " + port + " its client port (4444 unless started with --port)?", e);
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
        try {
            // A short connect deadline (a server list) must not cut a slow first handshake or greeting short.
            s.setSoTimeout((int) Math.max(timeout.toMillis(), 10_000));
            if (s instanceof SSLSocket tls) {
                handshake(tls);
            }
            return greeting.greet(s);
        } catch (Tls.RefusedCertificate e) {
            s.close();
            throw e;
        } catch (IOException e) {
            s.close();
            throw WrongPort.explain(host, port, s instanceof SSLSocket, e);
        } catch (RuntimeException e) {
            s.close();
            throw e;
        }
    }

    /** Runs the TLS handshake now, so that a refused certificate says why in plain words. */
    private static void handshake(SSLSocket tls) throws IOException {
        try {
            tls.startHandshake();
        } catch (SSLException e) {
            for (Throwable t = e; t != null; t = t.getCause()) {
                if (t instanceof Tls.ChangedCertificateException changed) {
                    throw new Tls.RefusedCertificate(changed.getMessage(), e);
                }
                if (t instanceof Tls.UnpinnedStandbyException unpinned) {
                    throw new IOException(unpinned.getMessage(), e);
                }
            }
            throw new IOException("TLS handshake failed: " + e.getMessage(), e);
        }
    }
}
