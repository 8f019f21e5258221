package org.ripv.server.security;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Optional;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
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

/**
 * {@code ?login USER} with the password in the attachment. The connection takes no further
 * request until its log-in is answered; the answer is waited for on one of a few threads of its
 * own (no more than the {@link LoginPool} holds, so a selector thread never waits) while the
 * password is checked on the pool; a blocked user or address is refused before any hashing; every
 * failure is one audit line; a refusal that ends the connection is sent before the close.
 */
public final class Logins implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Logins.class);

    /** Failed log-ins one connection may make before it is closed. */
    public static final int MAX_FAILED_PER_CONNECTION = 5;

    private final Supplier<PermitFile> permits;
    private final LoginThrottle throttle;
    private final LoginPool pool;
    private final ConnectionGate gate;
    /** Where client-port log-ins wait for their check: idle, no thread at all. */
    private final ThreadPoolExecutor waiting;

    public Logins(Supplier<PermitFile> permits, LoginThrottle throttle, LoginPool pool, ConnectionGate gate) {
        this.permits = permits;
        this.throttle = throttle;
        this.pool = pool;
        this.gate = gate;
        AtomicInteger n = new AtomicInteger();
        // One more than the pool holds: the pool, not this, decides when a flood is refused as busy.
        this.waiting = new ThreadPoolExecutor(0, pool.capacity() + 1, 10, TimeUnit.SECONDS, new SynchronousQueue<>(), r -> {
            Thread t = new Thread(r, "ripv-login-wait-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Answers a {@code ?login} from the client port, on a selector thread: the client's reading is
     * held and the log-in waits for its check elsewhere; the client reads on once it is answered.
     */
    public void loginLater(SocketHandler client, IncomingServerMessage request) {
        client.holdReading();
        gate.checking(client.clientId());
        try {
            waiting.execute(() -> {
                try {
                    login(client, request);
                } finally {
                    gate.checked(client.clientId());
                    client.resumeReading();
                }
            });
        } catch (RejectedExecutionException e) {
            gate.checked(client.clientId());
            String[] words = request.header().body().trim().split("\\s+");
            Audit.log(true, "login-busy", "user", words.length > 1 ? words[1] : "", "from",
                    client.remoteInetAddress().getHostAddress(), "via", "client " + client.clientId());
            client.send(refusal(request, ErrorCode.NOT_AVAILABLE, "too many log-ins at once; try again in a few seconds"));
            client.resumeReading();
        }
    }

    @Override
    public void close() {
        waiting.shutdownNow();
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
        byte[] raw = request.header().attachment().data();
        CharBuffer chars = StandardCharsets.UTF_8.decode(ByteBuffer.wrap(raw));
        char[] password = Arrays.copyOf(chars.array(), chars.limit());
        Arrays.fill(chars.array(), '\0');
        Check c = check(user, password, address, "client " + client.clientId());
        if (c.busy() != null) {
            client.send(refusal(request, ErrorCode.NOT_AVAILABLE, c.busy()));
            return;
        }
        if (c.block() != null && c.user() == null && !c.failed()) {
            client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN, tooMany(c.block())));
            return;
        }
        if (c.failed()) {
            int onConnection = client.failedLogin();
            if (c.block() != null) {
                client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN, "wrong user name or password; " + tooMany(c.block())));
            } else if (onConnection >= MAX_FAILED_PER_CONNECTION) {
                client.sendAndClose(refusal(request, ErrorCode.FORBIDDEN,
                        "wrong user name or password; too many failures, disconnecting"));
            } else {
                client.send(refusal(request, ErrorCode.FORBIDDEN, "wrong user name or password"));
            }
            return;
        }
        Optional<PermitFile.User> u = Optional.of(c.user());
        if (!gate.loggedIn(client.clientId())) {
            Audit.log(true, "login-refused", "user", user, "from", address, "client", client.clientId(), "reason", "server-full");
            client.sendAndClose(refusal(request, ErrorCode.NOT_AVAILABLE, "the server has " + gate.limits().maxLoggedIn()
                    + " clients logged in, the most it takes; try again later"));
            return;
        }
        client.loggedIn(user, u.get().roles());
        Audit.log(false, "login", "user", user, "from", address, "client", client.clientId());
        log.info("client {} ({}) logged in as {} {}", client.clientId(), client.remoteAddress(), user, u.get().roles());
        client.send(request.reply(Footer.ok(Ids.FID_LOGIN, "logged in as " + user + " (client " + client.clientId() + ")",
                new SessionInfo(client.clientId(), user, u.get().roles(), "RIPVServer"))));
    }

    /**
     * The outcome of checking a password: the user, or a failure (with the block it caused), or a
     * block in force before any hashing, or the pool too busy to check.
     */
    public record Check(PermitFile.User user, boolean failed, LoginThrottle.Block block, String busy) {}

    /**
     * Checks a password with the limits and the audit of every log-in, wherever it comes from (the
     * client port, the landing page). Clears the password.
     *
     * @param where what to name in the audit line, e.g. {@code client 100001} or {@code web}
     */
    public Check check(String user, char[] password, String address, String where) {
        try {
            LoginThrottle.Block block = throttle.admit(user, address);
            if (block != null && throttle.addressBlocked(address) == null) {
                // Trying a blocked name again counts against the address: a flood that keeps at it
                // is soon refused at connect, before the TLS handshake that each try costs.
                LoginThrottle.Block addressBlock = throttle.refusedWhileBlocked(address);
                block = addressBlock != null ? addressBlock : block;
            }
            if (block != null) {
                Audit.limited("login-refused " + user + " " + address, "login-refused", "user", user, "from", address, "via", where,
                        "reason", block.locked() ? "locked" : "blocked", "blocked", block.who(), "seconds-left", seconds(block));
                return new Check(null, false, block, null);
            }
            Optional<PermitFile.User> u;
            try {
                PermitFile file = permits.get();
                u = pool.run(() -> file.authenticate(user, password));
            } catch (LoginPool.Busy e) {
                Audit.log(true, "login-busy", "user", user, "from", address, "via", where);
                return new Check(null, false, null, e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return new Check(null, false, null, "interrupted");
            }
            if (u.isPresent()) {
                throttle.success(user, address);
                return new Check(u.get(), false, null, null);
            }
            LoginThrottle.Block caused = throttle.failure(user, address);
            Audit.log(true, "login-failed", "user", user, "from", address, "via", where,
                    "blocked", caused == null ? "no" : caused.who(), "seconds", caused == null ? 0 : seconds(caused));
            return new Check(null, true, caused, null);
        } finally {
            Arrays.fill(password, '\0');
        }
    }

    /** What to tell someone who is blocked. */
    public static String refusalText(LoginThrottle.Block b) {
        return tooMany(b);
    }

    private static String tooMany(LoginThrottle.Block b) {
        return "too many failed log-ins for this " + (b.who().startsWith("user") ? "user" : "address") + "; "
                + (b.locked() ? "locked for " : "try again in ") + seconds(b) + " s"
                + (b.locked() ? " or ask an admin to lift it (?unlock-login)" : "") + "; disconnecting";
    }

    private static long seconds(LoginThrottle.Block b) {
        return Math.max(1, (b.left().toMillis() + 999) / 1000);
    }

    private static OutgoingServerMessage refusal(IncomingServerMessage request, ErrorCode code, String text) {
        return request.reply(Footer.error(Ids.FID_LOGIN, code, text));
    }
}
