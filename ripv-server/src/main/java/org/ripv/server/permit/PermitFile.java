package org.ripv.server.permit;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * Who may log in and what each may do (docs/permit.md). A line-oriented text file:
 * <pre>
 * # comment
 * user alice pbkdf2-sha256$120000$SALT$HASH operators
 * user bob   pbkdf2-sha256$120000$SALT$HASH observers,db-reader
 * allow @operators  *                *   *
 * allow @observers  SerialPortServer *   dir
 * allow @observers  SerialPortServer *   ymodem:get *
 * deny  @observers  SerialPortServer *   *
 * quota @observers  100M
 * </pre>
 * Rules are read top to bottom and the first that applies to the user and matches the command
 * decides; when none does, the command is refused.
 */
public final class PermitFile {
    /** What a user is: name, stored hash, roles. */
    public record User(String name, String hash, List<String> roles) {
        public User {
            roles = List.copyOf(roles);
        }
    }

    /** The verdict on a command, with the rule that decided it. */
    public record Decision(boolean allowed, String because) {}

    /** The most roles one user may have (they travel with every request). */
    public static final int MAX_ROLES = 64;

    /** A user's upload quota when no {@code quota} line applies: 1 GiB. */
    public static final long DEFAULT_QUOTA = 1L << 30;

    /** {@code quota WHO BYTES}: how much a user may keep in the upload directory. */
    private record Quota(String who, long bytes) {}

    private final Path file;
    private final Map<String, User> users;
    private final List<Rule> rules;
    private final List<Quota> quotas;
    private final List<String> lines;

    private PermitFile(Path file, Map<String, User> users, List<Rule> rules, List<Quota> quotas, List<String> lines) {
        this.file = file;
        this.users = users;
        this.rules = rules;
        this.quotas = quotas;
        this.lines = lines;
    }

    /** The file a new server writes: roles for operators and observers, no users yet. */
    public static final String TEMPLATE = String.join("\n",
            "# RIPV permit file (docs/permit.md).",
            "# Add or change users with:  ripv passwd --permit THIS_FILE USER [--roles operators]",
            "#",
            "# user NAME HASH ROLE[,ROLE...]",
            "# allow|deny WHO SERVICE MAILBOX COMMAND-PATTERN",
            "#   WHO: a user, @role or *;  SERVICE: e.g. SerialPortServer, or RIPVServer for the server's",
            "#   ?upload, ?upload-cancel, ?download, ?delete, ?replace NAME (the right to upload with 'replace'),",
            "#   ?lock and ?unlock (other ? commands need only a log-in);",
            "#   MAILBOX: a handle such as ttyS0 or *;  COMMAND-PATTERN: the whole one-line command, * matching anything;",
            "#   ?read is reading a MailBox: watching its console (?watch), ?history, notifications.",
            "#   ?webhook URL (service RIPVServer) is adding a webhook notification.",
            "# The first rule that matches decides; a command no rule allows is refused.",
            "# quota WHO BYTES: how much a user may keep in the upload directory (first match; default 1G).",
            "",
            "# Operators command vehicles, change the database, replace and delete stored files.",
            "allow @operators * * *",
            "",
            "# Observers watch every vehicle's console and read its transcript (?read), fetch what was downloaded,",
            "# query and plot; they send nothing to a vehicle: an Iridium call's minutes are the operators'.",
            "# To let them list and offload, put above the deny line, e.g.:",
            "#   allow @observers SerialPortServer * dir*",
            "#   allow @observers SerialPortServer * ymodem:get *",
            "# They upload to the server only under free names (no 'replace', no ?delete), and the DatabaseServer",
            "# runs their SQL as its read-only user whatever their other roles (docs/database.md).",
            "allow @observers * * ?read",
            "deny  @observers SerialPortServer * *",
            "allow @observers DatabaseServer * *",
            "allow @observers DataVisServer * *",
            "allow @observers RIPVServer * ?upload*",
            "allow @observers RIPVServer * ?download *",
            "quota @observers 100M",
            "");

    /** Reads a permit file; a missing file is created from {@link #TEMPLATE}. */
    public static PermitFile load(Path file) throws IOException {
        if (!Files.exists(file)) {
            if (file.getParent() != null) {
                Files.createDirectories(file.getParent());
            }
            writeOwnerOnly(file, List.of(TEMPLATE.split("\n", -1)), false);
        }
        return parse(file, Files.readAllLines(file, StandardCharsets.UTF_8));
    }

    static PermitFile parse(Path file, List<String> lines) {
        Map<String, User> users = new LinkedHashMap<>();
        List<Rule> rules = new ArrayList<>();
        List<Quota> quotas = new ArrayList<>();
        int n = 0;
        for (String raw : lines) {
            n++;
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] w = line.split("\\s+", 5);
            String where = file + ":" + n + ": ";
            switch (w[0]) {
                case "user" -> {
                    if (w.length < 3) {
                        throw new IllegalArgumentException(where + "a user line is 'user NAME HASH [ROLES]'");
                    }
                    List<String> roles = w.length >= 4 ? Arrays.asList(w[3].split(",")) : List.of();
                    if (roles.size() > MAX_ROLES) {
                        throw new IllegalArgumentException(where + "user " + w[1] + " has " + roles.size() + " roles; at most "
                                + MAX_ROLES + " are allowed");
                    }
                    users.put(w[1], new User(w[1], w[2], roles));
                }
                case "allow", "deny" -> {
                    if (w.length < 5) {
                        throw new IllegalArgumentException(where + "a rule is '" + w[0] + " WHO SERVICE MAILBOX COMMAND-PATTERN'");
                    }
                    rules.add(Rule.parse(w[0].equals("allow"), w[1], w[2], w[3], w[4], line));
                }
                case "quota" -> {
                    if (w.length != 3) {
                        throw new IllegalArgumentException(where + "a quota is 'quota WHO BYTES', e.g. quota @observers 100M");
                    }
                    quotas.add(new Quota(w[1], bytes(w[2], where)));
                }
                default -> throw new IllegalArgumentException(where + "unknown line '" + w[0]
                        + "': lines start with user, allow, deny or quota");
            }
        }
        return new PermitFile(file, users, rules, List.copyOf(quotas), List.copyOf(lines));
    }

    /** {@code 500}, {@code 64K}, {@code 100M}, {@code 2G} (powers of 1024). */
    private static long bytes(String s, String where) {
        String t = s.toUpperCase(Locale.ROOT);
        long unit = t.endsWith("K") ? 1L << 10 : t.endsWith("M") ? 1L << 20 : t.endsWith("G") ? 1L << 30 : 1;
        try {
            long v = Long.parseLong(unit == 1 ? t : t.substring(0, t.length() - 1));
            if (v < 0 || v > Long.MAX_VALUE / unit) {
                throw new NumberFormatException();
            }
            return v * unit;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(where + "quota '" + s + "' is not a size like 500, 64K, 100M or 2G");
        }
    }

    /** The most bytes a user may keep in the upload directory: the first {@code quota} line for them, else {@link #DEFAULT_QUOTA}. */
    public long quota(User user) {
        for (Quota q : quotas) {
            if (q.who().equals("*") || q.who().equals(user.name())
                    || q.who().startsWith("@") && user.roles().contains(q.who().substring(1))) {
                return q.bytes();
            }
        }
        return DEFAULT_QUOTA;
    }

    public Optional<User> user(String name) {
        return Optional.ofNullable(users.get(name));
    }

    public List<User> users() {
        return List.copyOf(users.values());
    }

    /** Checks a password; unknown users take as long as known ones. */
    public Optional<User> authenticate(String name, char[] password) {
        User u = users.get(name);
        if (u == null) {
            Passwords.verifyDummy(password);
            return Optional.empty();
        }
        return Passwords.verify(password, u.hash()) ? Optional.of(u) : Optional.empty();
    }

    /** May this user run this command in this service's MailBox? */
    public Decision decide(User user, String serviceName, String handle, String command) {
        for (Rule r : rules) {
            if (r.appliesTo(user.name(), user.roles()) && r.matches(serviceName, handle, command)) {
                return new Decision(r.allow(), r.source());
            }
        }
        return new Decision(false, "no rule in the permit file allows it");
    }

    /**
     * Whether any command at all may be allowed for this user in this service's MailBox — for pages
     * that show a command line only to those who may use it. The rules are read in order as
     * {@link #decide} reads them: an allow for a vehicle's command (not a {@code ?} command such as
     * {@code ?read} or {@code ?key ctrl-c}) says yes; a deny of every command ({@code *}) ends it. Every command is still decided by
     * {@link #decide} when it is sent.
     */
    public boolean maySendSomething(User user, String serviceName, String handle) {
        for (Rule r : rules) {
            if (!r.appliesTo(user.name(), user.roles()) || !r.service().matcher(serviceName).matches()
                    || !r.mailbox().matcher(handle).matches()) {
                continue;
            }
            boolean every = r.command().pattern().equals(".*");
            // A rule about '?' commands (?read, ?key ctrl-c) is no command line's worth: those have controls of their own.
            if (r.allow() && (every || !r.command().pattern().startsWith(Pattern.quote("?")))) {
                return true;
            }
            if (!r.allow() && every) {
                return false;
            }
        }
        return false;
    }

    /**
     * Adds a user or changes an existing one's password (and roles, when given; the stored hash is
     * kept when the password is the same), rewriting the file through a temporary file so that a crash never leaves it half written.
     */
    public static void setUser(Path file, String name, char[] password, List<String> roles, int iterations) throws IOException {
        if (!name.matches("[A-Za-z0-9._@-]{1,64}")) {
            throw new IllegalArgumentException("a user name is 1–64 letters, digits, '.', '_', '@' or '-', got '" + name + "'");
        }
        PermitFile current = load(file);
        // The same password keeps its hash: a change of roles alone is not a password change, which
        // logs the user out everywhere (org.ripv.server.security.StaleLogins).
        String had = current.user(name).map(User::hash).orElse(null);
        String hash = had != null && had.split("\\$").length == 4 && had.split("\\$")[1].equals(String.valueOf(iterations))
                && Passwords.verify(password, had) ? had : Passwords.hash(password, iterations);
        List<String> out = new ArrayList<>();
        boolean replaced = false;
        for (String line : current.lines) {
            String[] w = line.strip().split("\\s+");
            if (w.length >= 3 && w[0].equals("user") && w[1].equals(name)) {
                List<String> keep = roles != null ? roles : (w.length >= 4 ? Arrays.asList(w[3].split(",")) : List.of());
                out.add(userLine(name, hash, keep));
                replaced = true;
            } else {
                out.add(line);
            }
        }
        if (!replaced) {
            int at = 0;
            for (int i = 0; i < out.size(); i++) {
                if (out.get(i).strip().startsWith("user ") || out.get(i).strip().startsWith("#")) {
                    at = i + 1;
                } else if (!out.get(i).isBlank()) {
                    break;
                }
            }
            out.add(at, userLine(name, hash, roles == null ? List.of() : roles));
        }
        writeOwnerOnly(file, out, true);
    }

    /** Writes through a temporary file readable by its owner only, then moves it into place. */
    private static void writeOwnerOnly(Path file, List<String> lines, boolean endWithNewline) throws IOException {
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        try {
            Files.createFile(tmp, PosixFilePermissions.asFileAttribute(
                    PosixFilePermissions.fromString("rw-------")));
        } catch (UnsupportedOperationException e) {
            Files.createFile(tmp);
        }
        String text = String.join("\n", lines) + (endWithNewline ? "\n" : "");
        Files.writeString(tmp, text, StandardCharsets.UTF_8);
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    private static String userLine(String name, String hash, List<String> roles) {
        return "user " + name + " " + hash + (roles.isEmpty() ? "" : " " + String.join(",", roles));
    }

    public Path path() {
        return file;
    }
}
