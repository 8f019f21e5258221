package org.ripv.client.panels;

import org.ripv.failover.ServerList;

/** A {@code host[:port]} as operators type it; IPv6 literals go in brackets ({@code [::1]:4444}). */
public record HostPort(String host, int port) {
    public HostPort {
        if (host == null || host.isBlank()) {
            throw new IllegalArgumentException("a server needs a host name");
        }
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("port " + port + " is outside 1-65535");
        }
    }

    /**
     * Parses {@code host}, {@code host:port}, {@code [v6]} or {@code [v6]:port}; or a list of
     * them ({@code host1,host2:4445}: an active server and its standbys), kept whole as the host,
     * which {@code ClientSocketHandler.connect} then tries in turn.
     */
    public static HostPort parse(String text, int defaultPort) {
        String t = text == null ? "" : text.strip();
        if (t.isEmpty()) {
            throw new IllegalArgumentException("enter a server as host or host:port");
        }
        if (t.indexOf(',') >= 0) {
            return new HostPort(ServerList.parse(t, defaultPort).toString(), defaultPort);
        }
        String host = t;
        String port = null;
        if (t.startsWith("[")) {
            int end = t.indexOf(']');
            if (end < 0) {
                throw new IllegalArgumentException("'" + t + "' has no closing ']'");
            }
            host = t.substring(1, end);
            String rest = t.substring(end + 1);
            if (!rest.isEmpty()) {
                if (!rest.startsWith(":")) {
                    throw new IllegalArgumentException("'" + t + "' is not [address]:port");
                }
                port = rest.substring(1);
            }
        } else if (t.indexOf(':') >= 0 && t.indexOf(':') == t.lastIndexOf(':')) {
            host = t.substring(0, t.indexOf(':'));
            port = t.substring(t.indexOf(':') + 1);
        }
        int p = defaultPort;
        if (port != null) {
            try {
                p = Integer.parseInt(port);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + port + "' in '" + t + "' is not a port number");
            }
        }
        return new HostPort(host, p);
    }

    @Override
    public String toString() {
        if (host.indexOf(',') >= 0) {
            return host;
        }
        return (host.indexOf(':') >= 0 ? "[" + host + "]" : host) + ":" + port;
    }
}
