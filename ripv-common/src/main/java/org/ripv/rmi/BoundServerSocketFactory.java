package org.ripv.rmi;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.rmi.server.RMIServerSocketFactory;

/**
 * RMI server sockets on one address: the server's registry and RMI object (its {@code --bind}),
 * and a service's exported object (its {@code --bind}). Equal factories share one port (RMI
 * compares them with equals).
 */
public record BoundServerSocketFactory(InetAddress address) implements RMIServerSocketFactory {
    @Override
    public ServerSocket createServerSocket(int port) throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        s.bind(new InetSocketAddress(address, port), 128);
        return s;
    }
}
