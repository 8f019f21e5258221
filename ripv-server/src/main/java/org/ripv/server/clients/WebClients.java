package org.ripv.server.clients;

import java.io.IOException;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.security.Audit;
import org.ripv.server.web.PostOfficeDoor;

/**
 * The web console's way into the Post Office: the {@link ClientAcceptor} adopts a page as an
 * in-process client already logged in (the web log-in checked the password with the same limits
 * and audit), so a page's requests meet every rule a socket client's do — with no socket and no
 * thread of its own (docs/web.md).
 */
public final class WebClients implements PostOfficeDoor {
    private final Supplier<ClientAcceptor> acceptor;

    public WebClients(Supplier<ClientAcceptor> acceptor) {
        this.acceptor = acceptor;
    }

    @Override
    public SocketHandler open(SocketHandler.Peer page, String user, List<String> roles) throws IOException {
        ClientAcceptor a = acceptor.get();
        if (a == null) {
            throw new IOException("the server is not taking clients yet");
        }
        SocketHandler h = a.adopt(page, user, roles);
        Audit.log(false, "web-client", "user", user, "from", page.address().getHostAddress(), "client", h.clientId());
        return h;
    }
}
