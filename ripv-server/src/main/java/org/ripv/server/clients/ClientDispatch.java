package org.ripv.server.clients;

import java.util.function.Consumer;
import java.util.function.Predicate;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.security.Logins;

/**
 * Requests arriving on client sockets (thesis figure 5-2: SocketHandler → RIPVServer's MailBox):
 * log-ins go to the log-in pool, everything else, once logged in, is stamped with the client's
 * badge and put into the Post Office; a closed connection is forgotten everywhere it left state.
 */
public final class ClientDispatch implements SocketHandler.Dispatcher {
    private final Logins logins;
    private final Predicate<String> beforeLogin;
    private final WaitingRequests waiting;
    private final Predicate<IncomingServerMessage> postOffice;
    private final Consumer<SocketHandler> closed;

    /**
     * @param beforeLogin the lines served before log-in (the command table's {@code ?help} and {@code ?ping})
     * @param postOffice delivers a request to the RIPV Post Office; false when it is full
     * @param closed     forgets a closed connection everywhere it left state (pending requests, uploads, locks…)
     */
    public ClientDispatch(Logins logins, Predicate<String> beforeLogin, WaitingRequests waiting,
                          Predicate<IncomingServerMessage> postOffice, Consumer<SocketHandler> closed) {
        this.logins = logins;
        this.beforeLogin = beforeLogin;
        this.waiting = waiting;
        this.postOffice = postOffice;
        this.closed = closed;
    }

    @Override
    public void received(SocketHandler client, IncomingServerMessage request) {
        Header h = request.header();
        String body = h.body().trim();
        if (body.equals("?login") || body.startsWith("?login ")) {
            logins.loginLater(client, request); // PBKDF2 on the log-in pool, never on this selector thread
            return;
        }
        if (!client.isLoggedIn() && !beforeLogin.test(body)) {
            client.send(request.reply(Footer.error(Ids.FID_LOGIN, ErrorCode.NOT_LOGGED_IN,
                    "log in first (?login USER with the password), then send '" + Header.abbreviate(body) + "'")));
            return;
        }
        String full = waiting.take(client.clientId(), h);
        if (full != null) {
            client.send(request.reply(Footer.error(Ids.FID_NONE, ErrorCode.NOT_AVAILABLE, full)));
            return;
        }
        IncomingServerMessage stamped = new IncomingServerMessage(
                h.withOrigin(client.badge(), client.roles()).withDestination(""));
        if (!postOffice.test(stamped)) {
            waiting.done(client.clientId(), h); // taken above, refused here: no longer waiting
            client.send(request.reply(Footer.error(Ids.FID_NONE, ErrorCode.NOT_AVAILABLE,
                    "the server is overloaded: too many requests waiting; try again shortly")));
        }
    }

    @Override
    public void closed(SocketHandler client) {
        closed.accept(client);
    }
}
