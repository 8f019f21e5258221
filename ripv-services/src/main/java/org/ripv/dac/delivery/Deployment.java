package org.ripv.dac.delivery;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import org.ripv.dac.DacException;
import org.ripv.dac.DacLedger;
import org.ripv.dac.FtpsPush;
import org.ripv.dac.Metadata;
import org.ripv.dac.ProfilePush;
import org.ripv.dac.ProfileSplitter;
import org.ripv.dac.QcConfig;
import org.ripv.dac.SftpPush;

/**
 * One deployment, as its file names it (JSON; paths relative to the file):
 *
 * <pre>{@code
 * {"glider": "rosie_713", "metadata": "dac-deployment.json", "qc": "dac-qc.yml",
 *  "folder": "rosie_713-dac",
 *  "destination": "sftp://rosie@dac.example.org/rosie_713-20190615",
 *  "key": "id_ecdsa", "known_hosts": "known_hosts"}
 * }</pre>
 *
 * or, for FTPS, {@code "destination": "ftps://USER@HOST[:PORT]/FOLDER"}, {@code "password_file"}
 * and {@code "trust"} (the server's certificate, PEM, or a PKCS#12/JKS trust store). Optional:
 * {@code min_depth_span}, {@code min_samples}, {@code filter} (the splitter's settings),
 * {@code first_retry_seconds} (5) and {@code max_retry_seconds} (600). Every problem is listed
 * in one refusal, and the metadata and QC files are read and checked here, so a deployment
 * with bad settings never starts.
 */
public record Deployment(Path file, String glider, Metadata metadata, QcConfig qc, Path folder, URI destination,
                         Path key, Path knownHosts, Path passwordFile, Path trust, ProfileSplitter splitter,
                         Duration firstRetry, Duration maxRetry) {

    private static final Set<String> KEYS = Set.of("glider", "metadata", "qc", "folder", "destination", "key", "known_hosts",
            "password_file", "trust", "min_depth_span", "min_samples", "filter", "first_retry_seconds", "max_retry_seconds");

    /** Reads and checks a deployment file. */
    public static Deployment read(Path file) throws DacException {
        JsonNode root;
        try {
            if (Files.size(file) > 64 * 1024) {
                throw new DacException(file + ": a deployment file is a few lines, not " + Files.size(file) + " bytes");
            }
            root = new ObjectMapper().readTree(file.toFile());
        } catch (IOException e) {
            throw new DacException(file + ": not a readable JSON deployment file: " + e.getMessage());
        }
        if (root == null || !root.isObject()) {
            throw new DacException(file + ": a deployment file is a JSON object");
        }
        Path base = file.toAbsolutePath().getParent();
        List<String> problems = new ArrayList<>();
        for (Iterator<String> it = root.fieldNames(); it.hasNext(); ) {
            String k = it.next();
            if (!KEYS.contains(k)) {
                problems.add("unknown key '" + k + "' (known: " + String.join(", ", KEYS.stream().sorted().toList()) + ")");
            }
        }
        String glider = text(root, "glider", true, problems);
        if (glider != null && !glider.matches("[A-Za-z0-9_]{1,32}")) {
            problems.add("glider must be the glider's name (letters, digits, _), not '" + glider + "'");
        }
        Path metaFile = path(base, text(root, "metadata", true, problems));
        Path qcFile = path(base, text(root, "qc", false, problems));
        String folderText = text(root, "folder", false, problems);
        Path folder = folderText == null ? base.resolve((glider == null ? "deployment" : glider) + "-dac") : path(base, folderText);
        String destText = text(root, "destination", true, problems);
        URI dest = null;
        if (destText != null) {
            try {
                dest = new URI(destText);
                if (!("sftp".equals(dest.getScheme()) || "ftps".equals(dest.getScheme())) || dest.getHost() == null
                        || dest.getUserInfo() == null) {
                    problems.add("destination must be sftp://USER@HOST[:PORT]/FOLDER or ftps://USER@HOST[:PORT]/FOLDER, not " + destText);
                    dest = null;
                }
            } catch (URISyntaxException e) {
                problems.add("destination is not a URL: " + e.getMessage());
            }
        }
        Path key = path(base, text(root, "key", false, problems));
        Path knownHosts = path(base, text(root, "known_hosts", false, problems));
        Path passwordFile = path(base, text(root, "password_file", false, problems));
        Path trust = path(base, text(root, "trust", false, problems));
        if (dest != null && dest.getScheme().equals("sftp")) {
            need(key, "key", "an SFTP destination needs the private key", problems);
            need(knownHosts, "known_hosts", "an SFTP destination needs the server's host key in a known-hosts file", problems);
        } else if (dest != null) {
            need(passwordFile, "password_file", "an FTPS destination needs the password's file", problems);
            need(trust, "trust", "an FTPS destination needs the server's certificate or a trust store", problems);
        }
        double span = number(root, "min_depth_span", ProfileSplitter.DEFAULT_MIN_DEPTH_SPAN, problems);
        int samples = (int) number(root, "min_samples", ProfileSplitter.DEFAULT_MIN_SAMPLES, problems);
        int filter = (int) number(root, "filter", ProfileSplitter.DEFAULT_FILTER, problems);
        long first = (long) number(root, "first_retry_seconds", 5, problems);
        long max = (long) number(root, "max_retry_seconds", 600, problems);
        if (first < 1 || max < first) {
            problems.add("first_retry_seconds must be at least 1 and max_retry_seconds at least that");
        }
        Metadata meta = null;
        QcConfig qc = QcConfig.none();
        if (metaFile != null) {
            try {
                meta = Metadata.read(metaFile);
            } catch (DacException e) {
                problems.add(e.getMessage());
            }
        }
        if (qcFile != null) {
            try {
                qc = QcConfig.read(qcFile);
            } catch (DacException e) {
                problems.add(e.getMessage());
            }
        }
        ProfileSplitter splitter = null;
        try {
            splitter = new ProfileSplitter(span, samples, filter);
        } catch (IllegalArgumentException e) {
            problems.add(e.getMessage());
        }
        if (!problems.isEmpty()) {
            throw new DacException(file + ": " + problems.size() + " problem" + (problems.size() == 1 ? "" : "s")
                    + " in the deployment: " + String.join("; ", problems));
        }
        return new Deployment(file, glider, meta, qc, folder, dest, key, knownHosts, passwordFile, trust,
                splitter, Duration.ofSeconds(first), Duration.ofSeconds(max));
    }

    /** The push to this deployment's destination, one connection attempt a call (the delivery retries). */
    ProfilePush push(DacLedger ledger) throws DacException {
        if (destination.getScheme().equals("sftp")) {
            return new SftpPush(destination, key, knownHosts, ledger, 1, Duration.ofSeconds(1));
        }
        return new FtpsPush(destination, passwordFile, trust, ledger);
    }

    /** The destination as shown: no password is ever in it. */
    public String where() {
        return destination.toString();
    }

    private static String text(JsonNode root, String key, boolean required, List<String> problems) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            if (required) {
                problems.add(key + " is missing");
            }
            return null;
        }
        if (!n.isTextual()) {
            problems.add(key + " must be a string, found " + n.getNodeType().toString().toLowerCase(java.util.Locale.ROOT) + " " + n);
            return null;
        }
        if (n.asText().isBlank()) {
            problems.add(key + " is empty");
            return null;
        }
        return n.asText();
    }

    private static double number(JsonNode root, String key, double otherwise, List<String> problems) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            return otherwise;
        }
        if (!n.isNumber() || n.asDouble() < 0) {
            problems.add(key + " must be a number of at least 0, found " + n);
            return otherwise;
        }
        return n.asDouble();
    }

    private static Path path(Path base, String text) {
        return text == null ? null : base.resolve(text).normalize();
    }

    private static void need(Path p, String key, String why, List<String> problems) {
        if (p == null) {
            problems.add(key + " is missing: " + why);
        } else if (!Files.isReadable(p)) {
            problems.add(key + ": no readable file at " + p);
        }
    }
}
