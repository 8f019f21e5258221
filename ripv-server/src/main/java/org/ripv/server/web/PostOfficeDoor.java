package org.ripv.server.web;

import java.io.IOException;
import java.util.List;
import org.ripv.server.handlers.SocketHandler;

/**
 * How a browser page becomes a client of the Post Office: the server adopts the page as an
 * in-process client (its own client id, the gate's admission, already logged in as the user the
 * web log-in checked). The page hands requests to the returned handler; the server writes replies
 * and pushes to {@code page}. No socket and no thread is made for it.
 */
public interface PostOfficeDoor {
    /**
     * @return the page's client; closing it is the page disconnecting
     * @throws IOException when the server takes no more clients (the message says so)
     */
    SocketHandler open(SocketHandler.Peer page, String user, List<String> roles) throws IOException;
}
