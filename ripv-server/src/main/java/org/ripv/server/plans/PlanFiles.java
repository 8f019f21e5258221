package org.ripv.server.plans;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

import org.ripv.messages.TableResult;
import org.ripv.plans.BehaviorFile;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.Waypoint;
import org.ripv.server.files.FileNames;
import org.ripv.server.files.FileStore;

/**
 * Where {@code ?plan}'s files come from and how they are read: a name in the upload store or
 * among the vehicle's downloads, read no further than the plan limits allow, the newest goto list
 * fetched from the vehicle; how a refused file is worded, how a checked one is tabled.
 */
record PlanFiles(PlanHost host, PlanLimits limits) {
    /** A name the glider's FAT file system takes: 8.3, a behaviour file's {@code .ma}. */
    private static final Pattern VEHICLE_NAME = Pattern.compile("[A-Za-z0-9_-]{1,8}\\.[Mm][Aa]");

    /** The file: in the upload store, else the vehicle's latest download of that name. */
    record Found(String where, Path path) {}

    Found find(String mailbox, String name) throws NoSuchFileException {
        FileNames.check(name);
        Path up = host.files().uploadDir().resolve(name);
        if (Files.isRegularFile(up)) {
            return new Found("the upload store", up);
        }
        String folder = FileStore.folderFor(mailbox);
        Path down = host.files().downloadDir().resolve(folder).resolve(name);
        if (Files.isRegularFile(down)) {
            return new Found("the vehicle's downloads (" + folder + "/" + name + ")", down);
        }
        throw new NoSuchFileException("no file '" + name + "' in the upload store nor among " + folder
                + "'s downloads; upload it (put FILE) or fetch it from the vehicle first");
    }

    PlanCheck read(Found f, String name) throws IOException {
        try (InputStream in = Files.newInputStream(f.path())) {
            return BehaviorFileReader.check(name, in, limits);
        }
    }

    static String refusal(PlanCheck c, Found f) {
        return c.problemText() + "\n" + c.problems().get(0).file() + " (" + f.where() + "): refused, " + c.problems().size()
                + " problem(s)";
    }

    byte[] readBounded(Found f) throws IOException {
        try (InputStream in = Files.newInputStream(f.path())) {
            return in.readNBytes(limits.maxBytes() + 1);
        }
    }

    static void vehicleName(String as) {
        if (!VEHICLE_NAME.matcher(as).matches()) {
            throw new IllegalArgumentException("'" + as + "' is not a name for the glider: behaviour files are NAME.ma with"
                    + " NAME 1 to 8 letters, digits, '_' or '-' (its file system takes 8.3 names), e.g. goto_l10.ma");
        }
    }

    private static final Pattern GOTO_FILE = Pattern.compile("(?i)goto_l\\d{1,3}\\.ma");

    /** The newest goto_l*.ma among the vehicle's downloads (at most 10,000 names looked at). */
    Path newestGotoFile(String mailbox) throws IOException {
        Path folder = host.files().downloadDir().resolve(FileStore.folderFor(mailbox));
        if (!Files.isDirectory(folder)) {
            return null;
        }
        Path newest = null;
        long at = Long.MIN_VALUE;
        int looked = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder)) {
            for (Path p : files) {
                if (++looked > 10_000) {
                    break;
                }
                if (GOTO_FILE.matcher(p.getFileName().toString()).matches() && Files.isRegularFile(p)) {
                    long t = Files.getLastModifiedTime(p).toMillis();
                    if (t > at) {
                        at = t;
                        newest = p;
                    }
                }
            }
        }
        return newest;
    }

    /** The waypoints as a table (n, lat, lon, comment), b_args as rows after them (n empty, lat the b_arg, lon its value). */
    static TableResult table(BehaviorFile f) {
        List<String[]> rows = new ArrayList<>();
        for (Waypoint wp : f.waypoints()) {
            rows.add(new String[] {Integer.toString(wp.n()), String.format(Locale.ROOT, "%.5f", wp.lat()),
                    String.format(Locale.ROOT, "%.5f", wp.lon()), wp.comment()});
        }
        return new TableResult("?plan check " + f.name(), List.of("n", "lat", "lon", "comment"),
                List.of("INTEGER", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false);
    }
}
