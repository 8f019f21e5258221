package org.ripv.server.notify;

import java.net.Inet4Address;
import java.net.Inet6Address;
import java.net.InetAddress;
import java.net.URI;
import java.net.UnknownHostException;
import org.ripv.security.AddressRanges;

/**
 * Where webhooks may go. A webhook makes the server send an HTTP request of a user's choosing from
 * inside its own network, so by default it refuses every address that is not on the public
 * Internet — loopback, this network, link-local (cloud metadata at 169.254.169.254), private,
 * carrier-grade NAT, unique-local IPv6, multicast — unless the operator allows a range with
 * {@code --webhook-allow CIDR[,CIDR...]} (or {@code any}). Every address a host name resolves to
 * must pass, at subscription and again at each delivery (docs/sessions.md#notifications).
 */
public record WebhookTargets(AddressRanges allowed, boolean any, String text) {
    /** The default: only public addresses. */
    public static final WebhookTargets PUBLIC_ONLY = new WebhookTargets(AddressRanges.NONE, false, "");

    /**
     * Parses {@code --webhook-allow}: a comma list of CIDR ranges ({@code 127.0.0.1/32},
     * {@code 10.0.0.0/8}, {@code fd00::/8}) or single addresses, or {@code any}.
     */
    public static WebhookTargets parse(String spec) {
        if (spec == null || spec.isBlank()) {
            return PUBLIC_ONLY;
        }
        boolean any = false;
        StringBuilder ranges = new StringBuilder();
        for (String part : spec.split(",")) {
            if (part.trim().equalsIgnoreCase("any")) {
                any = true;
            } else {
                ranges.append(part).append(',');
            }
        }
        try {
            return new WebhookTargets(AddressRanges.parse(ranges.toString()), any, spec.trim());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--webhook-allow: " + e.getMessage());
        }
    }

    /**
     * Resolves the URL's host and refuses it, with the reason, when any of its addresses is not
     * public and not allowed. Blocks on DNS: call it off the broker's threads.
     */
    public void check(URI url) {
        if (any) {
            return;
        }
        String host = url.getHost();
        if (host == null) {
            throw new IllegalArgumentException("a webhook URL needs a host");
        }
        String bare = host.startsWith("[") && host.endsWith("]") ? host.substring(1, host.length() - 1) : host;
        InetAddress[] all;
        try {
            all = InetAddress.getAllByName(bare);
        } catch (UnknownHostException e) {
            throw new IllegalArgumentException("cannot resolve the webhook's host '" + host + "'");
        }
        for (InetAddress a : all) {
            String kind = restricted(a);
            if (kind != null && !allowed.contains(a)) {
                throw new IllegalArgumentException("webhook host '" + host + "' is " + a.getHostAddress() + ", " + kind
                        + "; this server sends webhooks only to public addresses unless started with --webhook-allow "
                        + "(docs/sessions.md#notifications)" + (text.isEmpty() ? "" : "; allowed here: " + text));
            }
        }
    }

    /** What makes an address off limits by default, or null for a public one. */
    static String restricted(InetAddress a) {
        if (a.isLoopbackAddress()) {
            return "a loopback address";
        }
        if (a.isAnyLocalAddress()) {
            return "the unspecified address";
        }
        if (a.isLinkLocalAddress()) {
            return "a link-local address";
        }
        if (a.isSiteLocalAddress()) {
            return "a private address";
        }
        if (a.isMulticastAddress()) {
            return "a multicast address";
        }
        byte[] b = a.getAddress();
        if (a instanceof Inet4Address) {
            int first = b[0] & 0xff;
            int second = b[1] & 0xff;
            if (first == 0) {
                return "an address of 'this network' (0.0.0.0/8)";
            }
            if (first == 100 && second >= 64 && second < 128) {
                return "a carrier-grade NAT address (100.64.0.0/10)";
            }
            if (first == 198 && (second == 18 || second == 19)) {
                return "a benchmarking address (198.18.0.0/15)";
            }
            if (first >= 240) {
                return "a reserved address (240.0.0.0/4)";
            }
            return null;
        }
        if (a instanceof Inet6Address) {
            if ((b[0] & 0xfe) == 0xfc) {
                return "a unique-local IPv6 address (fc00::/7)";
            }
            // IPv4 inside IPv6 (NAT64 64:ff9b::/96, IPv4-compatible ::a.b.c.d, 6to4 2002::/16): judge the IPv4 part.
            byte[] v4 = null;
            if (b[0] == 0 && b[1] == 0x64 && (b[2] & 0xff) == 0xff && (b[3] & 0xff) == 0x9b) {
                v4 = new byte[] {b[12], b[13], b[14], b[15]};
            } else if (allZero(b, 0, 12)) {
                v4 = new byte[] {b[12], b[13], b[14], b[15]};
            } else if ((b[0] & 0xff) == 0x20 && (b[1] & 0xff) == 0x02) {
                v4 = new byte[] {b[2], b[3], b[4], b[5]};
            }
            if (v4 != null) {
                try {
                    String inner = restricted(InetAddress.getByAddress(v4));
                    return inner == null ? null : inner + " inside an IPv6 address";
                } catch (UnknownHostException e) {
                    return "an unusable address";
                }
            }
        }
        return null;
    }

    private static boolean allZero(byte[] b, int from, int to) {
        for (int i = from; i < to; i++) {
            if (b[i] != 0) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return text.isEmpty() ? "public addresses only" : text;
    }
}
