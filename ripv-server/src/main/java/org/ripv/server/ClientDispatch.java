package org.ripv.server;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.server.handlers.SocketHandler;

/**
 * Requests arriving on client sockets (thesis figure 5-2: SocketHandler → RIPVServer's MailBox):
 * log-ins go to the log-in pool, everything else, once logged in, is stamped with the client's
 * badge and put into the Post Office; a closed connection is forgotten everywhere it left state.
 */
final class ClientDispatch implements SocketHandler.Dispatcher {
    private final RIPVServer server;

    ClientDispatch(RIPVServer server) {
        this.server = server;
    }

    @Override
    public void received(SocketHandler client, IncomingServerMessage request) {
        Header h = request.header();
        String body = h.body().trim();
        if (body.equals("?login") || body.startsWith("?login ")) {
            server.security().logins().loginLater(client, request); // PBKDF2 on the log-in pool, never on this selector thread
            return;
        }
        if (!client.isLoggedIn() && !body.equals("?help") && !body.equals("?ping")) {
            client.send(request.reply(Footer.error(Ids.FID_LOGIN, ErrorCode.NOT_LOGGED_IN,
                    "log in first (?login USER with the password), then send '" + Header.abbreviate(body) + "'")));
            return;
        }
        String full = server.waiting().take(client.clientId(), h);
        if (full != null) {
            client.send(request.reply(Footer.error(Ids.FID_NONE, ErrorCode.NOT_AVAILABLE, full)));
            return;
        }
        IncomingServerMessage stamped = new IncomingServerMessage(
                h.withOrigin(client.badge(), client.roles()).withDestination(""));
        if (!server.deliver(stamped)) {
            server.waiting().done(client.clientId(), h); // taken above, refused here: no longer waiting
            client.send(request.reply(Footer.error(Ids.FID_NONE, ErrorCode.NOT_AVAILABLE,
                    "the server is overloaded: too many requests waiting; try again shortly")));
        }
    }

    @Override
    public void closed(SocketHandler client) {
        server.forgetClient(client);
        server.waiting().forget(client.clientId());
        server.security().gate().closed(client.clientId());
        server.pending().forgetClient(client.clientId());
        server.files().abortAll(client.clientId());
        if (server.sessions().clientClosed(client.clientId(), server.locks())) {
            server.workflows().lockReleased(null);
        }
    }
}
