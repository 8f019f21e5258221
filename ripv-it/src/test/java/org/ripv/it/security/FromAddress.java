package org.ripv.it.security;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import javax.net.SocketFactory;

/** Sockets from a chosen loopback source address (Linux routes all of 127/8 to lo): many "hosts" on one machine. */
final class FromAddress extends SocketFactory {
    private final SocketFactory inner;
    private final String source;

    FromAddress(SocketFactory inner, String source) {
        this.inner = inner;
        this.source = source;
    }

    @Override
    public Socket createSocket() throws IOException {
        Socket s = inner.createSocket();
        s.bind(new InetSocketAddress(source, 0));
        return s;
    }

    @Override
    public Socket createSocket(String host, int port) throws IOException {
        Socket s = createSocket();
        s.connect(new InetSocketAddress(host, port));
        return s;
    }

    @Override
    public Socket createSocket(String host, int port, InetAddress localHost, int localPort) {
        throw new UnsupportedOperationException();
    }

    @Override
    public Socket createSocket(InetAddress host, int port) throws IOException {
        Socket s = createSocket();
        s.connect(new InetSocketAddress(host, port));
        return s;
    }

    @Override
    public Socket createSocket(InetAddress address, int port, InetAddress localAddress, int localPort) {
        throw new UnsupportedOperationException();
    }
}
