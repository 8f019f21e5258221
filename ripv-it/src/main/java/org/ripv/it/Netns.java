package org.ripv.it;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Network namespaces for the multi-host test: hosts on one bridge that lives in a namespace of
 * its own (nothing is added to the machine's own network), a router namespace that masquerades
 * a private network behind it, and Java programs started inside them with {@code ip netns exec}.
 * Everything it made goes away on {@link #close}, on failure too; namespaces left by a run that
 * was killed are removed by the next. Used by the multi-host tests and {@code ./ripv bench hosts}.
 */
public final class Netns implements AutoCloseable {
    private static final String FAMILY = "ripvt";
    private final String prefix;
    private final List<String> namespaces = new ArrayList<>();
    private final List<Process> processes = new ArrayList<>();
    private final String bridgeNs;

    private Netns(String prefix) {
        this.prefix = prefix;
        this.bridgeNs = prefix + "sw";
    }

    /** Why network namespaces cannot be made here, or null when they can. */
    public static String unusable() {
        if (!"root".equals(System.getProperty("user.name"))) {
            return "needs root for network namespaces (ip netns); CI runs as root";
        }
        if (!onPath("ip") || !onPath("nft")) {
            return "needs ip (iproute2) and nft (nftables) on the PATH; .ci/run installs them";
        }
        try {
            String probe = FAMILY + "probe" + ProcessHandle.current().pid();
            sh("ip", "netns", "add", probe);
            sh("ip", "netns", "del", probe);
            return null;
        } catch (IOException e) {
            return "network namespaces are not allowed here: " + e.getMessage();
        }
    }

    /** True when {@code command} is an executable on the PATH. */
    public static boolean onPath(String command) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String dir : path.split(File.pathSeparator)) {
            Path p = Path.of(dir, command);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                return true;
            }
        }
        return false;
    }

    /** A fresh set, after removing what killed runs left. */
    public static Netns create() throws IOException {
        removeStale();
        Netns n = new Netns(FAMILY + ProcessHandle.current().pid() + "x");
        n.add(n.bridgeNs);
        n.in(n.bridgeNs, "ip", "link", "add", "br0", "type", "bridge");
        n.in(n.bridgeNs, "ip", "link", "set", "br0", "up");
        return n;
    }

    private static void removeStale() {
        try {
            for (String line : sh("ip", "netns", "list").split("\n")) {
                String name = line.split(" ")[0];
                if (!name.startsWith(FAMILY) || name.startsWith(FAMILY + "probe")) {
                    continue;
                }
                String digits = name.substring(FAMILY.length()).replaceAll("x.*", "");
                try {
                    if (ProcessHandle.of(Long.parseLong(digits)).isEmpty()) {
                        killAll(name);
                        sh("ip", "netns", "del", name);
                    }
                } catch (NumberFormatException | IOException ignored) {
                    // not one of ours
                }
            }
        } catch (IOException ignored) {
            // nothing to clean
        }
    }

    public String ns(String host) {
        return prefix + host;
    }

    private void add(String ns) throws IOException {
        sh("ip", "netns", "add", ns);
        namespaces.add(ns);
        in(ns, "ip", "link", "set", "lo", "up");
    }

    /** A host on the bridge: namespace, a veth pair to the bridge, an address. */
    public void host(String host, String cidr) throws IOException {
        String ns = ns(host);
        add(ns);
        sh("ip", "-n", ns, "link", "add", "eth0", "type", "veth", "peer", "name", host, "netns", bridgeNs);
        in(bridgeNs, "ip", "link", "set", host, "master", "br0");
        in(bridgeNs, "ip", "link", "set", host, "up");
        in(ns, "ip", "addr", "add", cidr, "dev", "eth0");
        in(ns, "ip", "link", "set", "eth0", "up");
    }

    /**
     * A host behind a NAT router: the router is on the bridge at {@code routerLan}; it and the
     * host share a private link; the router masquerades the host's connections out, and its
     * firewall drops every connection from outside in (as a home or ship's router does), so the
     * server can route to the host but never reach it.
     */
    public void natHost(String router, String routerLan, String host, String routerInner, String hostCidr, String hostGateway)
            throws IOException {
        host(router, routerLan);
        String r = ns(router);
        String h = ns(host);
        add(h);
        sh("ip", "-n", r, "link", "add", "eth1", "type", "veth", "peer", "name", "eth0", "netns", h);
        in(r, "ip", "addr", "add", routerInner, "dev", "eth1");
        in(r, "ip", "link", "set", "eth1", "up");
        in(h, "ip", "addr", "add", hostCidr, "dev", "eth0");
        in(h, "ip", "link", "set", "eth0", "up");
        in(h, "ip", "route", "add", "default", "via", hostGateway);
        in(r, "sysctl", "-q", "-w", "net.ipv4.ip_forward=1");
        nft(r, """
                table ip ripvnat {
                  chain masq { type nat hook postrouting priority 100; oifname "eth0" masquerade; }
                  chain guard { type filter hook forward priority 0; policy drop;
                    ct state established,related accept; iifname "eth1" accept; }
                }
                """);
    }

    /** Routes {@code net} from {@code host} through {@code via}. */
    public void route(String host, String net, String via) throws IOException {
        in(ns(host), "ip", "route", "add", net, "via", via);
    }

    /** Drops every packet in and out of a host (a cut link, as a firewall or a dead radio sees it). */
    public void cut(String host) throws IOException {
        nft(ns(host), """
                table inet ripvcut {
                  chain inbound { type filter hook input priority -10; policy drop; iifname "lo" accept; }
                  chain outbound { type filter hook output priority -10; policy drop; oifname "lo" accept; }
                }
                """);
    }

    public void mend(String host) throws IOException {
        in(ns(host), "nft", "delete", "table", "inet", "ripvcut");
    }

    private void nft(String ns, String rules) throws IOException {
        Path f = Files.createTempFile("ripv-nft", ".conf");
        try {
            Files.writeString(f, rules, StandardCharsets.UTF_8);
            in(ns, "nft", "-f", f.toString());
        } finally {
            Files.deleteIfExists(f);
        }
    }

    public String in(String ns, String... cmd) throws IOException {
        List<String> all = new ArrayList<>(List.of("ip", "netns", "exec", ns));
        all.addAll(List.of(cmd));
        return sh(all.toArray(String[]::new));
    }

    /** Starts a Java main class of this build inside a host's namespace, its output to a log. */
    public Process java(String host, Path log, String mainClass, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of("ip", "netns", "exec", ns(host),
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Xshare:auto",
                "-cp", System.getProperty("java.class.path"), mainClass));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        processes.add(p);
        return p;
    }

    public static String sh(String... cmd) throws IOException {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        try {
            if (!p.waitFor(30, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException(String.join(" ", cmd) + ": did not finish in 30 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            throw new IOException(String.join(" ", cmd) + " failed (" + p.exitValue() + "): " + out.strip());
        }
        return out;
    }

    private static void killAll(String ns) {
        try {
            for (String pid : sh("ip", "netns", "pids", ns).split("\\s+")) {
                if (!pid.isBlank()) {
                    ProcessHandle.of(Long.parseLong(pid.trim())).ifPresent(ProcessHandle::destroyForcibly);
                }
            }
        } catch (IOException | NumberFormatException ignored) {
            // gone already
        }
    }

    @Override
    public void close() {
        for (Process p : processes) {
            p.destroyForcibly();
        }
        for (Process p : processes) {
            try {
                p.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        for (int i = namespaces.size() - 1; i >= 0; i--) {
            killAll(namespaces.get(i));
            try {
                sh("ip", "netns", "del", namespaces.get(i));
            } catch (IOException ignored) {
                // best effort; the next run removes it
            }
        }
    }
}
