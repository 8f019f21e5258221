package org.ripv.security;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A list of IP address ranges in CIDR form ({@code 10.0.0.0/8, 127.0.0.1, fd00::/8}), as operators
 * write them in options such as the server's {@code --webhook-allow} and a {@code listen://}
 * link's {@code callers=}. Only literals are taken: a range never costs a DNS look-up.
 */
public final class AddressRanges {
    /** No range at all. */
    public static final AddressRanges NONE = new AddressRanges(List.of(), "");

    private final List<Range> ranges;
    private final String text;

    private AddressRanges(List<Range> ranges, String text) {
        this.ranges = ranges;
        this.text = text;
    }

    /**
     * Parses a comma list of addresses and CIDR ranges; blank gives {@link #NONE}.
     *
     * @throws IllegalArgumentException naming the part that is not an address or range
     */
    public static AddressRanges parse(String spec) {
        if (spec == null || spec.isBlank()) {
            return NONE;
        }
        List<Range> ranges = new ArrayList<>();
        for (String part : spec.split(",")) {
            String p = part.trim();
            if (!p.isEmpty()) {
                ranges.add(Range.parse(p));
            }
        }
        return new AddressRanges(List.copyOf(ranges), spec.trim());
    }

    public boolean isEmpty() {
        return ranges.isEmpty();
    }

    /** True when the address lies in one of the ranges (IPv4 and IPv6 ranges match their own family only). */
    public boolean contains(InetAddress address) {
        byte[] b = address.getAddress();
        return ranges.stream().anyMatch(r -> r.contains(b));
    }

    /** The ranges as they were written. */
    @Override
    public String toString() {
        return text;
    }

    private record Range(byte[] network, int bits) {
        static Range parse(String s) {
            int slash = s.indexOf('/');
            String addr = slash < 0 ? s : s.substring(0, slash);
            if (!addr.matches("[0-9A-Fa-f:.]+")) {
                throw new IllegalArgumentException("expected an IP address or CIDR range such as 10.0.0.0/8, not '" + s + "'");
            }
            byte[] net;
            try {
                net = InetAddress.getByName(addr).getAddress(); // a literal, checked above: no DNS look-up
            } catch (UnknownHostException e) {
                throw new IllegalArgumentException("'" + s + "' is not an IP address or CIDR range");
            }
            int bits;
            try {
                bits = slash < 0 ? net.length * 8 : Integer.parseInt(s.substring(slash + 1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + s + "': the prefix length is not a number");
            }
            if (bits < 0 || bits > net.length * 8) {
                throw new IllegalArgumentException("'" + s + "': the prefix length must be 0-" + net.length * 8);
            }
            return new Range(net, bits);
        }

        boolean contains(byte[] b) {
            if (b.length != network.length) {
                return false;
            }
            for (int i = 0; i < bits; i++) {
                int mask = 0x80 >> (i % 8);
                if ((b[i / 8] & mask) != (network[i / 8] & mask)) {
                    return false;
                }
            }
            return true;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Range r && r.bits == bits && Arrays.equals(r.network, network);
        }

        @Override
        public int hashCode() {
            return 31 * Arrays.hashCode(network) + bits;
        }
    }
}
