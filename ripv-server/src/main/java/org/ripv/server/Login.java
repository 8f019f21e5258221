package org.ripv.server;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Optional;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionInfo;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.permit.PermitFile;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** {@code ?login USER}, with the password in the request's attachment. */
final class Login {
    private static final Logger log = LoggerFactory.getLogger(Login.class);

    /** Failed log-ins one connection may make before it is closed. */
    static final int MAX_FAILED_LOGINS = 5;

    private Login() {}

    static OutgoingServerMessage login(RIPVServer server, SocketHandler client, IncomingServerMessage request) {
        String[] words = request.header().body().trim().split("\\s+");
        if (words.length != 2 || request.header().attachment() == null) {
            return request.reply(Footer.error(Ids.FID_LOGIN, ErrorCode.BAD_REQUEST,
                    "log in with '?login USER' and the password attached (the clients do this for you)"));
        }
        String user = words[1];
        byte[] raw = request.header().attachment().data();
        CharBuffer chars = StandardCharsets.UTF_8.decode(ByteBuffer.wrap(raw));
        char[] password = Arrays.copyOf(chars.array(), chars.limit());
        Arrays.fill(chars.array(), '\0');
        try {
            Optional<PermitFile.User> u = server.permits().authenticate(user, password);
            if (u.isEmpty()) {
                int failures = client.failedLogin();
                log.warn("client {} ({}): failed log-in as '{}' ({} on this connection)", client.clientId(),
                        client.remoteAddress(), user, failures);
                if (failures >= MAX_FAILED_LOGINS) {
                    // Guessing passwords costs a new connection (and its own PBKDF2 time) every few tries.
                    client.send(request.reply(Footer.error(Ids.FID_LOGIN, ErrorCode.FORBIDDEN,
                            "wrong user name or password; too many failures, disconnecting")));
                    client.close();
                    return null;
                }
                return request.reply(Footer.error(Ids.FID_LOGIN, ErrorCode.FORBIDDEN, "wrong user name or password"));
            }
            client.loggedIn(user, u.get().roles());
            log.info("client {} ({}) logged in as {} {}", client.clientId(), client.remoteAddress(), user, u.get().roles());
            return request.reply(Footer.ok(Ids.FID_LOGIN, "logged in as " + user + " (client " + client.clientId() + ")",
                    new SessionInfo(client.clientId(), user, u.get().roles(), "RIPVServer")));
        } finally {
            Arrays.fill(password, '\0');
        }
    }
}
