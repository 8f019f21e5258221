package org.ripv.service;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.rmi.RemoteException;
import java.time.Duration;
import org.ripv.outbound.CallChannel;
import org.ripv.outbound.OutboundHandshake;
import org.ripv.outbound.OutboundLimits;
import org.ripv.rmi.DeadlineSocketFactory;
import org.ripv.rmi.GenericRMIInterface;

/**
 * Outbound-only registration's connection: TCP to the server's outbound port within the connect
 * deadline, the HMAC handshake, then {@link GenericRMIInterface} calls both ways over it.
 */
final class OutboundDial {
    private OutboundDial() {}

    /**
     * Opens the connection to {@code host:port} for the service {@code name}; the server's calls
     * come back to {@code remote} over it.
     */
    static CallChannel open(String host, int port, String secret, String name, GenericRMIInterface remote)
            throws RemoteException {
        Socket socket = new Socket();
        String where = host + ":" + port;
        try {
            DeadlineSocketFactory f = DeadlineSocketFactory.fromSystem();
            socket.connect(new InetSocketAddress(host, port), f.connectMillis());
            socket.setSoTimeout(Math.max(f.readMillis(), 5_000));
            DataInputStream in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
            OutboundHandshake.service(in, out, secret, name);
            return new CallChannel(socket, where, remote, OutboundLimits.MAX_FRAME,
                    Duration.ofMillis(Math.max(f.readMillis(), 5_000)));
        } catch (SocketTimeoutException e) {
            close(socket);
            throw new RemoteException("could not reach the server's outbound port " + where + ": timed out", e);
        } catch (IOException e) {
            close(socket);
            throw new RemoteException("could not connect to the server's outbound port " + where + ": " + e.getMessage(), e);
        } catch (RuntimeException e) {
            close(socket);
            throw e;
        }
    }

    private static void close(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
