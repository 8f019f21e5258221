package org.ripv.messages;

import java.io.Serializable;

/**
 * Who a message came from: the six-digit client id the server gave the connection on connect,
 * and the name of the user logged in on it (empty before log-in).
 */
public record IdBadge(String clientId, String user) implements Serializable {
    public IdBadge {
        Ids.require(clientId);
        user = user == null ? "" : user;
    }

    /** The badge of the server itself, for messages it originates. */
    public static final IdBadge SERVER = new IdBadge("000000", "RIPVServer");
}
