package org.ripv.server.services;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.HexFormat;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The service secret ({@code DATA/service.secret}): made on the server's first start, readable
 * by its owner only, and required of every service that registers.
 */
public final class ServiceSecret {
    private static final Logger log = LoggerFactory.getLogger(ServiceSecret.class);

    private ServiceSecret() {}

    /** Reads the secret, or writes a new random one when there is none usable. */
    public static String loadOrCreate(Path file) throws IOException {
        if (Files.exists(file)) {
            String s = Files.readString(file, StandardCharsets.UTF_8).trim();
            if (s.length() >= 16) {
                return s;
            }
            log.warn("{} holds no usable secret; writing a new one", file);
        }
        byte[] b = new byte[32];
        new SecureRandom().nextBytes(b);
        String s = HexFormat.of().formatHex(b);
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        try {
            Files.createFile(tmp, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        } catch (UnsupportedOperationException e) {
            Files.createFile(tmp);
        }
        Files.writeString(tmp, s + "\n", StandardCharsets.UTF_8);
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        log.info("wrote a new service secret to {} (readable by its owner only)", file);
        return s;
    }
}
