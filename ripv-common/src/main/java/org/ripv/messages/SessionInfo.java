package org.ripv.messages;

import java.util.List;

/** The answer to {@code ?login} and {@code ?whoami}: who the server believes you are. */
public record SessionInfo(String clientId, String user, List<String> roles, String server) implements Result {
    public SessionInfo {
        roles = roles == null ? List.of() : List.copyOf(roles);
    }
}
