package org.ripv.commands;

import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The values the options of {@code ?} commands take, as picocli converters, so that each is read
 * and refused with the same words wherever it appears ({@code --last N}, {@code --since ISO-TIME}).
 * picocli puts the option's name before the message: {@code Invalid value for option '--since': …}.
 */
public final class OptionValues {
    /** The most lines, records or receipts one reply lists. */
    public static final int MAX_LAST = 1000;

    private OptionValues() {}

    /** {@code 2026-11-23T14:00:00Z}, {@code 2026-11-23T14:00} (UTC) or {@code 2026-11-23} (its start, UTC). */
    public static final class IsoTime implements ITypeConverter<Instant> {
        @Override
        public Instant convert(String s) {
            Instant t = parse(s);
            if (t == null) {
                throw new TypeConversionException("--since takes 2026-11-23T14:00:00Z, 2026-11-23T14:00 or 2026-11-23, not '"
                        + s + "'");
            }
            return t;
        }

        /** The instant, or null when {@code s} is none of the three forms. */
        public static Instant parse(String s) {
            try {
                return Instant.parse(s);
            } catch (DateTimeParseException ignored) {
                // try the shorter forms
            }
            try {
                return LocalDateTime.parse(s).toInstant(ZoneOffset.UTC);
            } catch (DateTimeParseException ignored) {
                // try a date
            }
            try {
                return LocalDate.parse(s).atStartOfDay(ZoneOffset.UTC).toInstant();
            } catch (DateTimeParseException e) {
                return null;
            }
        }
    }

    /** A count from 1 to {@link #MAX_LAST}: how many of the latest to list. */
    public static final class Last implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String s) {
            return count(s, MAX_LAST, "from 1 to " + MAX_LAST);
        }
    }

    /** A whole number from 1 ({@code ?history --last N}: the transcript page bounds it itself). */
    public static final class Count implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String s) {
            return count(s, Integer.MAX_VALUE, "from 1");
        }
    }

    /** A whole number from 1 to {@code max}, or picocli's conversion error in the words of {@code --last}. */
    private static int count(String s, int max, String range) {
        int n;
        try {
            n = Integer.parseInt(s);
        } catch (NumberFormatException e) {
            n = 0;
        }
        if (n < 1 || n > max) {
            throw new TypeConversionException("--last takes a whole number " + range + ", not '" + s + "'");
        }
        return n;
    }
}
