package org.ripv.server.security;

import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.permit.PermitFile;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Log-ins must not outlive a change of their user (issue 33 item 4). Run at every reload of the
 * permit file: a user who was removed or whose password changed is logged out everywhere (each
 * connection told why, each web session ended); a user whose roles changed has the new roles on
 * every open connection and web session at once. Every request is stamped with its client's roles
 * as it arrives, and services decide by those (the DatabaseServer's read-write connection needs
 * {@code operators} or {@code db-writer}), so the next request of a demoted operator acts as an
 * observer's.
 */
public final class StaleLogins implements Consumer<PermitFile> {
    private static final Logger log = LoggerFactory.getLogger(StaleLogins.class);

    /** What a reload changed: users to log out, and the new roles of users who stay. */
    public record Changes(Set<String> ended, Map<String, List<String>> roles) {
        public Changes {
            ended = Set.copyOf(ended);
            roles = Map.copyOf(roles);
        }

        public boolean none() {
            return ended.isEmpty() && roles.isEmpty();
        }
    }

    private final Supplier<? extends Collection<SocketHandler>> clients;
    private final List<Consumer<Changes>> listeners = new CopyOnWriteArrayList<>();
    private PermitFile last;

    /** {@code clients}: every connected client, socket and web page alike. */
    public StaleLogins(PermitFile current, Supplier<? extends Collection<SocketHandler>> clients) {
        this.last = Objects.requireNonNull(current, "current");
        this.clients = Objects.requireNonNull(clients, "clients");
    }

    /** Also tells {@code listener} (the web console's sessions) of each change. */
    public void onChange(Consumer<Changes> listener) {
        listeners.add(listener);
    }

    /** The users a change from {@code before} to {@code after} logs out or gives new roles. */
    public static Changes between(PermitFile before, PermitFile after) {
        Set<String> ended = new HashSet<>();
        Map<String, List<String>> roles = new HashMap<>();
        for (PermitFile.User was : before.users()) {
            PermitFile.User now = after.user(was.name()).orElse(null);
            if (now == null || !now.hash().equals(was.hash())) {
                ended.add(was.name());
            } else if (!now.roles().equals(was.roles())) {
                roles.put(was.name(), now.roles());
            }
        }
        return new Changes(ended, roles);
    }

    @Override
    public synchronized void accept(PermitFile now) {
        Changes c = between(last, now);
        last = now;
        if (c.none()) {
            return;
        }
        for (SocketHandler client : clients.get()) {
            String user = client.badge().user();
            if (c.ended().contains(user)) {
                log.info("client {} of {} logged out: the permit file no longer has that log-in", client.clientId(), user);
                Audit.log(false, "logout", "user", user, "client", client.clientId(), "reason", "password-changed-or-removed");
                client.sendAndClose(new OutgoingServerMessage(Header.request(0, "", "", Priority.URGENT),
                        Footer.error(Ids.FID_LOGIN, ErrorCode.NOT_LOGGED_IN, "your password was changed or your user removed in the"
                                + " permit file; log in again")));
            } else if (c.roles().containsKey(user)) {
                client.loggedIn(user, c.roles().get(user));
                log.info("client {} of {} now has roles {}", client.clientId(), user, c.roles().get(user));
            }
        }
        for (Consumer<Changes> l : listeners) {
            l.accept(c);
        }
    }
}
