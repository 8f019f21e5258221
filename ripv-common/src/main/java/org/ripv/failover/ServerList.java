package org.ripv.failover;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * The servers a service or client may use, in the order given: {@code host1[:port],host2[:port]}.
 * A host without a port gets the default one; {@code //host} (the thesis's form) is accepted.
 * IPv6 literals go in brackets ({@code [::1]:4444}).
 *
 * @param servers one or more, in order
 */
public record ServerList(List<Endpoint> servers) {
    /** Longest list accepted: a typo should not make a client dial hundreds of hosts. */
    public static final int MAX_SERVERS = 8;

    /** One server. */
    public record Endpoint(String host, int port) {
        public Endpoint {
            Objects.requireNonNull(host, "host");
            if (host.isBlank() || port < 1 || port > 65535) {
                throw new IllegalArgumentException("not a server address: " + host + ":" + port);
            }
        }

        @Override
        public String toString() {
            return (host.indexOf(':') >= 0 ? "[" + host + "]" : host) + ":" + port;
        }
    }

    public ServerList {
        servers = List.copyOf(servers);
        if (servers.isEmpty()) {
            throw new IllegalArgumentException("no server given");
        }
    }

    /** A list of one. */
    public static ServerList of(String host, int port) {
        return new ServerList(List.of(new Endpoint(host, port)));
    }

    /**
     * Parses {@code host1[:port],host2[:port]}.
     *
     * @throws IllegalArgumentException with the offending part named
     */
    public static ServerList parse(String text, int defaultPort) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("no server given: HOST[:PORT][,HOST2[:PORT]]");
        }
        List<Endpoint> out = new ArrayList<>();
        for (String part : text.split(",", -1)) {
            if (out.size() == MAX_SERVERS) {
                throw new IllegalArgumentException("'" + text + "': at most " + MAX_SERVERS + " servers");
            }
            Endpoint e = endpoint(part.trim(), defaultPort, text);
            if (!out.contains(e)) {
                out.add(e);
            }
        }
        return new ServerList(out);
    }

    private static Endpoint endpoint(String t, int defaultPort, String whole) {
        String p = t.startsWith("//") ? t.substring(2) : t;
        String host = p;
        String port = null;
        if (p.startsWith("[")) {
            int close = p.indexOf(']');
            if (close < 0) {
                throw bad(whole, t, "an unclosed [");
            }
            host = p.substring(1, close);
            String rest = p.substring(close + 1);
            if (!rest.isEmpty()) {
                if (!rest.startsWith(":")) {
                    throw bad(whole, t, "text after ]");
                }
                port = rest.substring(1);
            }
        } else {
            int colon = p.lastIndexOf(':');
            if (colon >= 0 && p.indexOf(':') == colon) {
                host = p.substring(0, colon);
                port = p.substring(colon + 1);
            }
        }
        if (host.isEmpty()) {
            throw bad(whole, t, "no host");
        }
        int n = defaultPort;
        if (port != null) {
            try {
                n = Integer.parseInt(port);
            } catch (NumberFormatException e) {
                throw bad(whole, t, "the port is not a number");
            }
        }
        if (n < 1 || n > 65535) {
            throw bad(whole, t, "the port is not 1 to 65535");
        }
        return new Endpoint(host, n);
    }

    private static IllegalArgumentException bad(String whole, String part, String why) {
        return new IllegalArgumentException("'" + whole + "' is not HOST[:PORT][,HOST2[:PORT]]: '" + part + "': " + why);
    }

    /** The first server. */
    public Endpoint first() {
        return servers.get(0);
    }

    public int size() {
        return servers.size();
    }

    /** The server after index {@code i}, round the list. */
    public int next(int i) {
        return (i + 1) % servers.size();
    }

    public Endpoint get(int i) {
        return servers.get(i);
    }

    /** Which of how many, for log lines: "" for a list of one. */
    public String position(int i) {
        return servers.size() == 1 ? "" : " (server " + (i + 1) + " of " + servers.size() + ")";
    }

    @Override
    public String toString() {
        return String.join(",", servers.stream().map(Endpoint::toString).toList());
    }
}
