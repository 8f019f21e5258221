package org.ripv.server.security;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Optional;
import java.util.function.Supplier;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.SessionInfo;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.permit.PermitFile;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code ?login USER} with the password in the attachment. Runs on the connection's reader
 * thread, which waits while the password is checked on the {@link LoginPool}; a blocked user or
 * address is refused before any hashing; every failure is one audit line; a refusal that ends
 * the connection is sent before the close.
 */
public final class Logins {
    private static final Logger log = LoggerFactory.getLogger(Logins.class);

    /** Failed log-ins one connection may make before it is closed. */
    public static final int MAX_FAILED_PER_CONNECTION = 5;

    private final Supplier<PermitFile> permits;
    private final LoginThrottle throttle;
    private final LoginPool pool;
    private final ConnectionGate gate;

    public Logins(Supplier<PermitFile> permits, LoginThrottle throttle, LoginPool pool, ConnectionGate gate) {
        this.permits = permits;
        this.throttle = throttle;
        this.pool = pool;
        this.gate = gate;
    }

    /** Answers a {@code ?login} request on the client's connection. */
    public void login(SocketHandler client, IncomingServerMessage request) {
        String[] words = request.header().body().trim().split("\\s+");
        if (words.length != 2 || request.header().attachment() == null) {
            client.send(refusal(request, ErrorCode.BAD_REQUEST,
                    "log in with '?login USER' and the password attached (the clients do this for you)"));
            return;
        }
        if (client.isLoggedIn()) {
            client.send(refusal(request, ErrorCode.BAD_REQUEST, "already logged in as " + client.badge().user()));
            return;
        }
        String user = words[1];
        String address = client.remoteInetAddress().getHostAddress();
        LoginThrottle.Block block = throttle.blocked(user, address);
        if (block != null) {
            Audit.log(true, "login-refused", "user", user, "from", address, "client", client.clientId(),
                    "reason", block.locked() ? "locked" : "blocked", "blocked", block.who(), "seconds-left", seconds(block));
            client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN, tooMany(block)));
            return;
        }
        byte[] raw = request.header().attachment().data();
        CharBuffer chars = StandardCharsets.UTF_8.decode(ByteBuffer.wrap(raw));
        char[] password = Arrays.copyOf(chars.array(), chars.limit());
        Arrays.fill(chars.array(), '\0');
        Optional<PermitFile.User> u;
        try {
            PermitFile file = permits.get();
            u = pool.run(() -> file.authenticate(user, password));
        } catch (LoginPool.Busy e) {
            Audit.log(true, "login-busy", "user", user, "from", address, "client", client.clientId());
            client.send(refusal(request, ErrorCode.NOT_AVAILABLE, e.getMessage()));
            return;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            client.close();
            return;
        } finally {
            Arrays.fill(password, '\0');
        }
        if (u.isEmpty()) {
            failed(client, request, user, address);
            return;
        }
        if (!gate.loggedIn(client.clientId())) {
            Audit.log(true, "login-refused", "user", user, "from", address, "client", client.clientId(), "reason", "server-full");
            client.sendAndClose(refusal(request, ErrorCode.NOT_AVAILABLE, "the server has " + gate.limits().maxLoggedIn()
                    + " clients logged in, the most it takes; try again later"));
            return;
        }
        throttle.success(user);
        client.loggedIn(user, u.get().roles());
        Audit.log(false, "login", "user", user, "from", address, "client", client.clientId());
        log.info("client {} ({}) logged in as {} {}", client.clientId(), client.remoteAddress(), user, u.get().roles());
        client.send(request.reply(Footer.ok(Ids.FID_LOGIN, "logged in as " + user + " (client " + client.clientId() + ")",
                new SessionInfo(client.clientId(), user, u.get().roles(), "RIPVServer"))));
    }

    private void failed(SocketHandler client, IncomingServerMessage request, String user, String address) {
        int onConnection = client.failedLogin();
        LoginThrottle.Block block = throttle.failure(user, address);
        Audit.log(true, "login-failed", "user", user, "from", address, "client", client.clientId(),
                "on-connection", onConnection, "blocked", block == null ? "no" : block.who(),
                "seconds", block == null ? 0 : seconds(block));
        if (block != null) {
            client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN, "wrong user name or password; " + tooMany(block)));
        } else if (onConnection >= MAX_FAILED_PER_CONNECTION) {
            client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN,
                    "wrong user name or password; too many failures, disconnecting"));
        } else {
            client.send(refusal(request, ErrorCode.FORBIDDEN, "wrong user name or password"));
        }
    }

    private static String tooMany(LoginThrottle.Block b) {
        return "too many failed log-ins for this " + (b.who().startsWith("user") ? "user" : "address") + "; "
                + (b.locked() ? "locked for " : "try again in ") + seconds(b) + " s"
                + (b.locked() ? " or ask an admin to lift it (?unlock-login)" : "") + "; disconnecting";
    }

    private static long seconds(LoginThrottle.Block b) {
        return Math.max(1, (b.left().toMillis() + 999) / 1000);
    }

    private static org.ripv.messages.OutgoingServerMessage refusal(IncomingServerMessage request, ErrorCode code, String text) {
        return request.reply(Footer.error(Ids.FID_LOGIN, code, text));
    }
}
