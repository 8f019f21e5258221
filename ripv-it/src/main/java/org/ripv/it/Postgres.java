package org.ripv.it;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Comparator;

/**
 * A throw-away PostgreSQL cluster in a network namespace of its own (the standby's state
 * database in the multi-host tests and {@code ./ripv bench hosts}). PostgreSQL refuses to run as
 * root, so it runs as the {@code postgres} user ({@code runuser}), in a temporary directory that
 * goes away on {@link #close}. Trust authentication, for the namespaces' network only.
 */
public final class Postgres implements AutoCloseable {
    private final Path dir;
    private final Path bin;
    private final String address;

    private Postgres(Path dir, Path bin, String address) {
        this.dir = dir;
        this.bin = bin;
        this.address = address;
    }

    /** Why a cluster cannot be made here, or null. */
    public static String unusable() {
        if (bin() == null) {
            return "needs the PostgreSQL server binaries (initdb, pg_ctl under /usr/lib/postgresql/*/bin); .ci/run installs them";
        }
        if (!Netns.onPath("runuser")) {
            return "needs runuser (util-linux) to run PostgreSQL as the postgres user";
        }
        try {
            Netns.sh("id", "postgres");
        } catch (IOException e) {
            return "needs a postgres system user (the postgresql package makes it)";
        }
        String tmp = System.getProperty("java.io.tmpdir");
        try {
            // The cluster lives in a temporary directory the postgres user must reach (a /tmp of mode 700 bars it).
            Netns.sh("runuser", "-u", "postgres", "--", "test", "-x", tmp);
        } catch (IOException e) {
            return "needs a temporary directory the postgres user can enter: " + tmp + " is closed to it"
                    + " (chmod 1777 " + tmp + ", or run with -Djava.io.tmpdir=DIR)";
        }
        return null;
    }

    private static Path bin() {
        Path root = Path.of("/usr/lib/postgresql");
        if (!Files.isDirectory(root)) {
            return null;
        }
        try (var versions = Files.list(root)) {
            return versions.map(v -> v.resolve("bin")).filter(b -> Files.isExecutable(b.resolve("pg_ctl")))
                    .max(Comparator.naturalOrder()).orElse(null);
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Makes host {@code host} at {@code cidr} on the namespaces' bridge and starts a cluster there,
     * listening on its address, port 5432, trusting clients from {@code clients} (a CIDR).
     */
    public static Postgres start(Netns net, String host, String cidr, String clients) throws IOException {
        net.host(host, cidr);
        Path bin = bin();
        Path dir = Files.createTempDirectory("ripv-pg");
        Netns.sh("chown", "postgres", dir.toString());
        String address = cidr.substring(0, cidr.indexOf('/'));
        Postgres pg = new Postgres(dir, bin, address);
        try {
            Netns.sh("runuser", "-u", "postgres", "--", bin.resolve("initdb").toString(), "-D", dir.resolve("data").toString(),
                    "-A", "trust", "-U", "postgres");
            Files.writeString(dir.resolve("data").resolve("pg_hba.conf"), "host all all " + clients + " trust\n",
                    StandardCharsets.UTF_8, StandardOpenOption.APPEND);
            net.in(net.ns(host), "runuser", "-u", "postgres", "--", bin.resolve("pg_ctl").toString(), "-D",
                    dir.resolve("data").toString(), "-o", "-p 5432 -k " + dir + " -c listen_addresses=" + address
                            + " -c fsync=off -c max_connections=40", "-l", dir.resolve("log").toString(), "-w", "start");
        } catch (IOException | RuntimeException e) {
            pg.close();
            throw e;
        }
        return pg;
    }

    /** The JDBC URL of its {@code postgres} database. */
    public String url() {
        return "jdbc:postgresql://" + address + ":5432/postgres";
    }

    @Override
    public void close() {
        try {
            if (Files.exists(dir.resolve("data").resolve("postmaster.pid"))) {
                Netns.sh("runuser", "-u", "postgres", "--", bin.resolve("pg_ctl").toString(), "-D", dir.resolve("data").toString(),
                        "-m", "immediate", "stop");
            }
        } catch (IOException ignored) {
            // the namespace's end kills it anyway
        }
        try {
            Netns.sh("rm", "-rf", dir.toString());
        } catch (IOException ignored) {
            // a temporary directory
        }
    }
}
