package org.ripv.plans;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.surfacing.DegreesMinutes;

/**
 * Reads a behaviour file line by line as the glider does, collecting every problem with its
 * line. Comments run from {@code #} to the end of the line, also straight after a value
 * ({@code -1# loop}); words are separated by spaces or tabs; CR LF and LF both end a line.
 *
 * <p>Bounded: it reads at most {@code maxBytes} and a line of at most {@code maxLineChars}
 * (a longer one stops the read with that line's number), keeps at most {@code maxWaypoints + 1}
 * waypoints (the rest are only counted) and {@code maxProblems} problems. Control bytes (other
 * than tab) anywhere and non-ASCII outside comments are refused: comments may hold a degree
 * sign, as files written by some tools do.
 */
public final class BehaviorFileReader {
    private static final Pattern BARG = Pattern.compile(
            "b_arg:[ \\t]*([A-Za-z_][A-Za-z0-9_]*)[ \\t]*\\(([^()]*)\\)[ \\t]*(\\S*)[ \\t]*(.*)");
    private static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_]{0,63}");
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d{1,15}(\\.\\d{0,15})?|\\.\\d{1,15})([eE][+-]?\\d{1,3})?");
    private static final Pattern INTEGER = Pattern.compile("[+-]?\\d{1,9}");

    private enum Block { NONE, BARG, WAYPOINTS }

    private final String name;
    private final PlanLimits limits;
    private final List<PlanProblem> problems = new ArrayList<>();
    private final List<BArg> bargs = new ArrayList<>();
    private final Map<String, Integer> bargLines = new HashMap<>();
    private final List<Waypoint> waypoints = new ArrayList<>();
    private String behavior;
    private Block block = Block.NONE;
    private int blockStart;
    private int bargBlockLine;
    private int waypointsBlockLine;
    private boolean sawBargBlock;
    private int waypointCount;
    private int firstWaypointLine;
    private boolean tooManyReported;
    private boolean stopped;

    private BehaviorFileReader(String name, PlanLimits limits) {
        this.name = name;
        this.limits = limits;
    }

    /** Reads {@code in} (not closed) as the file {@code name}. */
    public static PlanCheck check(String name, InputStream in, PlanLimits limits) throws IOException {
        return new BehaviorFileReader(name, limits).read(in);
    }

    public static PlanCheck check(String name, byte[] bytes, PlanLimits limits) {
        try {
            return check(name, new ByteArrayInputStream(bytes), limits);
        } catch (IOException e) {
            throw new IllegalStateException(e); // not from a byte array
        }
    }

    private PlanCheck read(InputStream in) throws IOException {
        MessageDigest sha = sha256();
        byte[] lineBytes = new byte[limits.maxLineChars() + 1];
        byte[] buffer = new byte[8192];
        int len = 0;
        int lineNo = 1;
        long total = 0;
        int n;
        outer:
        while ((n = in.read(buffer)) > 0) {
            total += n;
            if (total > limits.maxBytes()) {
                problem(lineNo, "the file is longer than " + limits.maxBytes() + " bytes: not a behaviour file; nothing more was read");
                stopped = true;
                break;
            }
            sha.update(buffer, 0, n);
            for (int i = 0; i < n; i++) {
                byte b = buffer[i];
                if (b == '\n') {
                    line(lineNo++, lineBytes, len);
                    len = 0;
                    if (stopped) {
                        break outer;
                    }
                } else if (len == lineBytes.length) {
                    problem(lineNo, "the line is longer than " + limits.maxLineChars() + " characters; nothing more was read");
                    stopped = true;
                    break outer;
                } else {
                    lineBytes[len++] = b;
                }
            }
        }
        if (!stopped && len > 0) {
            line(lineNo, lineBytes, len);
        } else if (!stopped) {
            lineNo--;
        }
        if (!stopped) {
            end(Math.max(lineNo, 1));
        }
        if (!problems.isEmpty()) {
            return new PlanCheck(null, problems);
        }
        return new PlanCheck(new BehaviorFile(name, behavior, bargs, waypoints, HexFormat.of().formatHex(sha.digest())), List.of());
    }

    private void line(int lineNo, byte[] bytes, int len) {
        if (len > 0 && bytes[len - 1] == '\r') {
            len--;
        }
        int comment = -1;
        for (int i = 0; i < len; i++) {
            int c = bytes[i] & 0xff;
            if ((c < 0x20 && c != '\t') || c == 0x7f) {
                problem(lineNo, String.format(Locale.ROOT, "control byte 0x%02X at column %d: a behaviour file is plain text", c, i + 1));
                return;
            }
            if (c == '#' && comment < 0) {
                comment = i;
            }
            if (c >= 0x80 && comment < 0) {
                problem(lineNo, String.format(Locale.ROOT, "non-ASCII byte 0x%02X at column %d outside a comment: the glider reads ASCII", c, i + 1));
                return;
            }
        }
        int codeEnd = comment < 0 ? len : comment;
        String code = new String(bytes, 0, codeEnd, StandardCharsets.US_ASCII).trim();
        String remark = comment < 0 ? "" : new String(bytes, comment + 1, len - comment - 1, StandardCharsets.ISO_8859_1).trim();
        if (!code.isEmpty()) {
            code(lineNo, code, remark);
        }
    }

    private void code(int lineNo, String code, String remark) {
        if (code.startsWith("<")) {
            tag(lineNo, code);
            return;
        }
        if (code.regionMatches(true, 0, "behavior_name", 0, 13) && code.substring(13).trim().startsWith("=")) {
            behaviorName(lineNo, code.substring(code.indexOf('=') + 1).trim());
            return;
        }
        switch (block) {
            case BARG -> barg(lineNo, code, remark);
            case WAYPOINTS -> waypoint(lineNo, code, remark);
            case NONE -> problem(lineNo, "'" + Quote.cut(code) + "' outside a block: only behavior_name=, <start:b_arg> and "
                    + "<start:waypoints> blocks and comments are read");
        }
    }

    private void behaviorName(int lineNo, String value) {
        if (block != Block.NONE) {
            problem(lineNo, "behavior_name= inside a block");
        } else if (behavior != null) {
            problem(lineNo, "a second behavior_name=: a file holds one behaviour");
        } else if (!NAME.matcher(value).matches()) {
            problem(lineNo, "behavior_name '" + Quote.cut(value) + "' is not a behaviour name");
        } else if (!SlocumVocabulary.knownBehavior(value)) {
            problem(lineNo, "unknown behaviour '" + value + "': the glider knows " + SlocumVocabulary.behaviors());
        } else {
            behavior = value;
        }
        if (behavior == null) {
            behavior = "";
        }
    }

    private void tag(int lineNo, String code) {
        String tag = code.replaceAll("[ \\t]", "");
        if (behavior == null) {
            problem(lineNo, "behavior_name= must come before " + Quote.cut(tag));
            behavior = "";
        }
        switch (tag.toLowerCase(Locale.ROOT)) {
            case "<start:b_arg>" -> open(lineNo, Block.BARG, tag);
            case "<start:waypoints>" -> open(lineNo, Block.WAYPOINTS, tag);
            case "<end:b_arg>" -> close(lineNo, Block.BARG, tag);
            case "<end:waypoints>" -> close(lineNo, Block.WAYPOINTS, tag);
            default -> problem(lineNo, "unknown tag '" + Quote.cut(code) + "': the tags are <start:b_arg>, <end:b_arg>, "
                    + "<start:waypoints> and <end:waypoints>");
        }
    }

    private void open(int lineNo, Block b, String tag) {
        if (block != Block.NONE) {
            problem(lineNo, tag + " inside the block started at line " + blockStart + " (no " + endTag(block) + " before it)");
            return;
        }
        if (b == Block.BARG ? sawBargBlock : waypointsBlockLine > 0) {
            problem(lineNo, "a second " + tag + ": a file has one");
        }
        block = b;
        blockStart = lineNo;
        if (b == Block.BARG) {
            sawBargBlock = true;
            bargBlockLine = lineNo;
        } else {
            waypointsBlockLine = lineNo;
        }
    }

    private void close(int lineNo, Block b, String tag) {
        if (block != b) {
            problem(lineNo, tag + " without its start tag" + (block == Block.NONE ? "" : " (the block open is from line " + blockStart + ")"));
            return;
        }
        block = Block.NONE;
    }

    private static String endTag(Block b) {
        return b == Block.BARG ? "<end:b_arg>" : "<end:waypoints>";
    }

    private void barg(int lineNo, String code, String remark) {
        Matcher m = BARG.matcher(code);
        if (!m.matches()) {
            problem(lineNo, "'" + Quote.cut(code) + "' is not b_arg: NAME(UNITS) VALUE");
            return;
        }
        String argName = m.group(1);
        String units = m.group(2).trim();
        String value = m.group(3);
        if (argName.length() > 64) {
            problem(lineNo, "b_arg name '" + Quote.cut(argName) + "' is too long");
            return;
        }
        if (!SlocumVocabulary.knownUnit(units)) {
            problem(lineNo, "unknown unit '" + Quote.cut(units) + "' of b_arg " + argName + ": units are those of masterdata "
                    + "(enum, nodim, m, s, sec, bool, X, deg, rad, lat, lon, …)");
            return;
        }
        if (value.isEmpty()) {
            problem(lineNo, "b_arg " + argName + " has no value");
            return;
        }
        if (!NUMBER.matcher(value).matches()) {
            problem(lineNo, "b_arg " + argName + " value '" + Quote.cut(value) + "' is not a number");
            return;
        }
        if (!m.group(4).isEmpty()) {
            problem(lineNo, "b_arg " + argName + ": '" + Quote.cut(m.group(4)) + "' after the value; start a comment with #");
            return;
        }
        Integer before = bargLines.putIfAbsent(argName.toLowerCase(Locale.ROOT), lineNo);
        if (before != null) {
            problem(lineNo, "b_arg " + argName + " is set again (first at line " + before + ")");
            return;
        }
        double v = Double.parseDouble(value);
        if (units.equalsIgnoreCase("lat") || units.equalsIgnoreCase("lon")) {
            try {
                DegreesMinutes.parse(value, units.equalsIgnoreCase("lat"));
            } catch (IllegalArgumentException e) {
                problem(lineNo, "b_arg " + argName + ": " + e.getMessage());
                return;
            }
        }
        bargs.add(new BArg(lineNo, argName, units, value, v, remark));
    }

    private void waypoint(int lineNo, String code, String remark) {
        String[] words = code.split("[ \\t]+");
        if (words.length != 2) {
            problem(lineNo, "a waypoint is LON LAT (two numbers), not '" + Quote.cut(code) + "'");
            return;
        }
        waypointCount++;
        if (firstWaypointLine == 0) {
            firstWaypointLine = lineNo;
        }
        if (waypointCount > limits.maxWaypoints()) {
            if (!tooManyReported) {
                tooManyReported = true;
                problem(lineNo, "more than " + limits.maxWaypoints() + " waypoints: the firmware takes at most "
                        + limits.maxWaypoints() + " (goto_list's num_waypoints)");
            }
            return; // counted, not kept: a billion waypoints cost a counter
        }
        try {
            double lon = DegreesMinutes.parse(words[0], false);
            double lat = DegreesMinutes.parse(words[1], true);
            waypoints.add(new Waypoint(waypointCount - 1, lineNo, words[0], words[1], lat, lon, remark));
        } catch (IllegalArgumentException e) {
            problem(lineNo, e.getMessage());
        }
    }

    private void end(int lastLine) {
        if (block != Block.NONE) {
            problem(blockStart, (block == Block.BARG ? "<start:b_arg>" : "<start:waypoints>") + " has no " + endTag(block)
                    + " (the file ends at line " + lastLine + ")");
        }
        if (behavior == null) {
            problem(1, "no behavior_name= line: the glider does not know what this file is for");
            return;
        }
        if (behavior.isEmpty()) {
            return; // its problem is reported
        }
        boolean isGoto = behavior.equalsIgnoreCase("goto_list");
        if (!isGoto && waypointsBlockLine > 0) {
            problem(waypointsBlockLine, "a waypoints list in a " + behavior + " file: only goto_list reads one");
        }
        if (isGoto) {
            gotoChecks(lastLine);
        }
    }

    private void gotoChecks(int lastLine) {
        if (waypointsBlockLine == 0) {
            problem(lastLine, "a goto_list file without <start:waypoints>: the glider would have nowhere to go");
        }
        BArg num = bargs.stream().filter(b -> b.name().equalsIgnoreCase("num_waypoints")).findFirst().orElse(null);
        if (num == null) {
            if (bargLines.containsKey("num_waypoints")) {
                return; // its line has a problem already
            }
            problem(Math.max(bargBlockLine, 1), "no b_arg num_waypoints(nodim): the glider reads that many waypoints (0 without it)");
            return;
        }
        if (!INTEGER.matcher(num.text()).matches()) {
            problem(num.line(), "num_waypoints '" + num.text() + "' is not a whole number");
            return;
        }
        int declared = Integer.parseInt(num.text());
        if (declared > limits.maxWaypoints()) {
            problem(num.line(), "num_waypoints is " + declared + ": the firmware takes at most " + limits.maxWaypoints());
        } else if (declared != waypointCount) {
            problem(num.line(), "num_waypoints is " + declared + " but the list has " + waypointCount + " waypoint(s)"
                    + (firstWaypointLine > 0 ? " (from line " + firstWaypointLine + ")" : ""));
        } else if (declared < 1) {
            problem(num.line(), "num_waypoints is " + declared + ": a goto list needs at least one waypoint");
        }
        bargs.stream().filter(b -> b.name().equalsIgnoreCase("initial_wpt")).findFirst().ifPresent(b -> {
            if (!INTEGER.matcher(b.text()).matches()) {
                problem(b.line(), "initial_wpt '" + b.text() + "' is not a whole number");
                return;
            }
            long v = Long.parseLong(b.text());
            if (v < -2 || v >= declared) {
                problem(b.line(), "initial_wpt " + v + " is not a waypoint of the list: 0 to " + (declared - 1)
                        + ", -1 (one after the last achieved) or -2 (the closest)");
            }
        });
    }

    private void problem(int lineNo, String reason) {
        if (problems.size() < limits.maxProblems()) {
            problems.add(new PlanProblem(name, lineNo, reason));
        } else if (problems.size() == limits.maxProblems()) {
            problems.add(new PlanProblem(name, lineNo, "more problems follow; fix these first"));
            stopped = true;
        }
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
