package org.ripv.slocum;

import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * How a Slocum glider's files are recognised, by name and by their first bytes: DBA text (the
 * output of {@code dbd2asc}), binary files ({@code .dbd}, {@code .sbd}, … and their compressed
 * {@code .dcd}, {@code .scd}, …) and sensor-list cache files ({@code CRC.cac}). One place for the
 * server and the DatabaseServer, so that what the server sends to the database is what the
 * database can read (docs/database.md).
 */
public final class SlocumFiles {
    /** The first line of a DBA file. */
    public static final String DBA_LABEL = "dbd_label: DBD_ASC(dinkum_binary_data_ascii)file";
    /** What the first line of a binary file says after {@code dbd_label:}. */
    public static final String BINARY_LABEL = "DBD(dinkum_binary_data)file";
    private static final byte[] DBA = DBA_LABEL.getBytes(StandardCharsets.US_ASCII);
    private static final byte[] LABEL_TAG = "dbd_label:".getBytes(StandardCharsets.US_ASCII);
    private static final Pattern CRC = Pattern.compile("[0-9a-f]{8}");
    /** How far into a file its first line is looked for. */
    private static final int FIRST_LINE = 128;

    private SlocumFiles() {}

    /** True when {@code start} (a file's first bytes) begins with the DBA label line. */
    public static boolean isDba(byte[] start) {
        if (start.length < DBA.length + 1) {
            return false;
        }
        for (int i = 0; i < DBA.length; i++) {
            if (start[i] != DBA[i]) {
                return false;
            }
        }
        byte next = start[DBA.length];
        return next == '\n' || next == '\r' || next == ' ' || next == '\t';
    }

    /** True when the file's first line is a binary file's label ({@code dbd_label: DBD(dinkum_binary_data)file}). */
    public static boolean hasBinaryLabel(byte[] data) {
        if (data.length < LABEL_TAG.length) {
            return false;
        }
        for (int i = 0; i < LABEL_TAG.length; i++) {
            if (data[i] != LABEL_TAG[i]) {
                return false;
            }
        }
        int end = 0;
        while (end < Math.min(data.length, FIRST_LINE) && data[end] != '\n') {
            end++;
        }
        return new String(data, 0, end, StandardCharsets.ISO_8859_1).contains(BINARY_LABEL);
    }

    /** The name without a folder ({@code TTY1/6B016A2E.CAC} as the server stores fetched files). */
    public static String baseName(String name) {
        return name.substring(Math.max(name.lastIndexOf('/'), name.lastIndexOf('\\')) + 1);
    }

    /** True for a sensor-list cache file's name, such as {@code 6b016a2e.cac} or {@code 00CDA96E.CAC}. */
    public static boolean isCacheName(String name) {
        String n = baseName(name).toLowerCase(Locale.ROOT);
        return n.endsWith(".cac") && CRC.matcher(n.substring(0, n.length() - 4)).matches();
    }

    /** True for a compressed binary file's name: a three-letter extension ending in {@code cd} ({@code .dcd}, {@code .tcd}). */
    public static boolean isCompressedName(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        int dot = n.lastIndexOf('.');
        return dot >= 0 && n.length() - dot == 4 && n.charAt(dot + 2) == 'c' && n.charAt(dot + 3) == 'd';
    }

    /** True for a binary file's name, plain or compressed ({@code .dbd}, {@code .sbd}, {@code .dcd}, …; not {@code .mrg}). */
    public static boolean isBinaryName(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        return n.matches(".*\\.[a-z][bc]d") && !n.endsWith(".mrg");
    }

    /** The glider's name from the header's {@code filename:} tag (before the first '-'), or null. */
    public static String vehicle(byte[] data) {
        String head = new String(data, 0, Math.min(data.length, 4096), StandardCharsets.ISO_8859_1);
        for (String line : head.split("\r?\n")) {
            if (line.startsWith("filename:") || line.startsWith("full_filename:")) {
                String f = line.substring(line.indexOf(':') + 1).strip();
                int dash = f.indexOf('-');
                return dash > 0 ? f.substring(0, dash) : f;
            }
        }
        return null;
    }
}
