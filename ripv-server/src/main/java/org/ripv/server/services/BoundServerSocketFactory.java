package org.ripv.server.services;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.rmi.server.RMIServerSocketFactory;
import java.util.Objects;

/**
 * Server sockets for the RMI registry and the server's RMI object, bound to {@code --bind} when
 * given. Equal factories let both share one port (RMI compares them with equals).
 */
public record BoundServerSocketFactory(InetAddress address) implements RMIServerSocketFactory {
    @Override
    public ServerSocket createServerSocket(int port) throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        s.bind(new InetSocketAddress(address, port), 128);
        return s;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof BoundServerSocketFactory other && Objects.equals(address, other.address);
    }

    @Override
    public int hashCode() {
        return Objects.hashCode(address);
    }
}
