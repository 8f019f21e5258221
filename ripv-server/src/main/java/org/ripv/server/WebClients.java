package org.ripv.server;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.security.Audit;
import org.ripv.server.web.PostOfficeDoor;

/**
 * The web console's way into the Post Office: a loopback connection whose server end the
 * {@link ClientAcceptor} adopts as a client already logged in (the web log-in checked the
 * password with the same limits and audit), so a page's requests meet every rule a socket
 * client's do. The one-shot listener is closed at once, and a connection that is not ours (another
 * local process racing to the port) is refused.
 */
final class WebClients implements PostOfficeDoor {
    private final Supplier<ClientAcceptor> acceptor;

    WebClients(Supplier<ClientAcceptor> acceptor) {
        this.acceptor = acceptor;
    }

    @Override
    public Socket open(String user, List<String> roles, String address) throws IOException {
        ClientAcceptor a = acceptor.get();
        if (a == null) {
            throw new IOException("the server is not taking clients yet");
        }
        Socket client = new Socket();
        try (ServerSocketChannel once = ServerSocketChannel.open().bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 1)) {
            client.connect(once.getLocalAddress(), 5_000);
            SocketChannel ours = once.accept(); // connected already: returns at once
            if (((InetSocketAddress) ours.getRemoteAddress()).getPort() != client.getLocalPort()) {
                ours.close();
                throw new IOException("another local process connected to the web console's loopback port first");
            }
            client.setTcpNoDelay(true);
            SocketHandler h = a.adopt(ours, user, roles);
            Audit.log(false, "web-client", "user", user, "from", address, "client", h.clientId());
            return client;
        } catch (IOException | RuntimeException e) {
            client.close();
            throw e;
        }
    }
}
