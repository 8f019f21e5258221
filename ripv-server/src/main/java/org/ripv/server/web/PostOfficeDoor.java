package org.ripv.server.web;

import java.io.IOException;
import java.net.Socket;
import java.util.List;

/**
 * How a browser page becomes a client of the Post Office: the server adopts one end of a
 * loopback connection as a client (its own SocketHandler, client id, bounded reply queue),
 * already logged in as the user the web log-in checked, and hands back the other end, on which
 * the page's requests travel as ordinary frames.
 */
public interface PostOfficeDoor {
    /**
     * @param address the browser's address, for the server's log lines
     * @return the client's end, greeting not yet exchanged
     * @throws IOException when the server takes no more clients (the message says so)
     */
    Socket open(String user, List<String> roles, String address) throws IOException;
}
