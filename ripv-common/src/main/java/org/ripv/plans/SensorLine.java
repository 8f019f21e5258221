package org.ripv.plans;

import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * One {@code sensor:NAME(UNITS)=VALUE} line of a surface dialog, or the echo of a {@code put}
 * ({@code sensor:NAME=VALUE}, no units). Leading blanks are allowed, anything after the value is not.
 */
public record SensorLine(String name, String units, double value) {
    private static final Pattern LINE = Pattern.compile(
            "\\s*sensor:\\s*([A-Za-z_][A-Za-z0-9_]{0,63})(?:\\(([^()]{0,16})\\))?\\s*=\\s*([+-]?(?:\\d{1,15}(?:\\.\\d{0,15})?|\\.\\d{1,15})(?:[eE][+-]?\\d{1,3})?)\\s*");

    public static Optional<SensorLine> parse(String line) {
        if (line == null || line.length() > 200) {
            return Optional.empty();
        }
        Matcher m = LINE.matcher(line);
        if (!m.matches()) {
            return Optional.empty();
        }
        return Optional.of(new SensorLine(m.group(1).toLowerCase(Locale.ROOT), m.group(2) == null ? "" : m.group(2),
                Double.parseDouble(m.group(3))));
    }
}
