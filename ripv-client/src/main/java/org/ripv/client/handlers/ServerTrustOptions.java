package org.ripv.client.handlers;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * How a client trusts the server it connects to (picocli mixin of the CLI and the GUI launcher):
 * {@code --plain} for a test lab's plain TCP, else TLS with the certificates remembered in
 * {@code --known-hosts}.
 */
public final class ServerTrustOptions {
    @Option(names = "--plain", description = "Connect over plain TCP, to a server started with --plain (a test lab).")
    boolean plain;

    @Option(names = "--known-hosts", paramLabel = "FILE",
            description = "Where server certificates are remembered on first use (default $RIPV_KNOWN_HOSTS or ~/.ripv/known_hosts).")
    Path knownHosts;

    /** Whether {@code --plain} was given. */
    public boolean plain() {
        return plain;
    }

    /** {@code --known-hosts}, or null when not given. */
    public Path knownHosts() {
        return knownHosts;
    }
}
