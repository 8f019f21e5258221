package org.ripv.services.ingest;

import java.io.IOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.List;
import java.util.Map;

/**
 * Writes decoded Slocum data as the DBA text {@code dbd2asc} prints: its 14 header lines, the
 * sensor names, units and byte sizes, then one row a cycle with a space after every value,
 * {@code NaN} where a sensor was not updated. Numbers are printed as C's {@code printf} prints
 * them there: 1- and 2-byte integers as integers, floats with {@code %g} (6 significant digits),
 * doubles with {@code %.15g}.
 */
public final class DbaText {
    private final Appendable out;
    private final byte[] sizes;
    private final StringBuilder line = new StringBuilder();

    private DbaText(Appendable out, List<SlocumSensor> sensors) {
        this.out = out;
        this.sizes = new byte[sensors.size()];
        for (int i = 0; i < sizes.length; i++) {
            sizes[i] = (byte) sensors.get(i).bytes();
        }
    }

    /** Writes the header and the label lines; rows follow with {@link #row}. */
    public static DbaText start(Appendable out, Map<String, String> tags, List<SlocumSensor> sensors) throws IOException {
        String name = tags.getOrDefault("full_filename", tags.getOrDefault("filename", ""));
        String ext = tags.getOrDefault("filename_extension", "");
        String eight = tags.getOrDefault("the8x3_filename", "");
        out.append(DbaReader.LABEL).append('\n')
                .append("encoding_ver: 2\n")
                .append("num_ascii_tags: 14\n")
                .append("all_sensors: ").append(tags.getOrDefault("all_sensors", "F").equals("T") ? "1" : "0").append('\n')
                .append("filename: ").append(name).append('\n')
                .append("the8x3_filename: ").append(eight).append('\n')
                .append("filename_extension: ").append(ext).append('\n')
                .append("filename_label: ").append(name).append('-').append(ext).append('(').append(eight).append(")\n")
                .append("mission_name: ").append(tags.getOrDefault("mission_name", "")).append('\n')
                .append("fileopen_time: ").append(tags.getOrDefault("fileopen_time", "")).append('\n')
                .append("sensors_per_cycle: ").append(Integer.toString(sensors.size())).append('\n')
                .append("num_label_lines: 3\n")
                .append("num_segments: 1\n")
                .append("segment_filename_0: ").append(name).append('\n');
        StringBuilder names = new StringBuilder();
        StringBuilder units = new StringBuilder();
        StringBuilder bytes = new StringBuilder();
        for (SlocumSensor s : sensors) {
            names.append(s.name()).append(' ');
            units.append(s.units()).append(' ');
            bytes.append(s.bytes()).append(' ');
        }
        out.append(names).append('\n').append(units).append('\n').append(bytes).append('\n');
        return new DbaText(out, sensors);
    }

    /** Writes one row. */
    public void row(double[] values) throws IOException {
        line.setLength(0);
        for (int i = 0; i < sizes.length; i++) {
            double v = values[i];
            if (Double.isNaN(v)) {
                line.append("NaN");
            } else if (sizes[i] <= 2) {
                line.append((long) v);
            } else {
                line.append(g(v, sizes[i] == 4 ? 6 : 15));
            }
            line.append(' ');
        }
        out.append(line).append('\n');
    }

    /** C's {@code %.Pg} of a finite double: P significant digits, trailing zeros dropped. */
    static String g(double v, int precision) {
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        if (v == 0) {
            return 1 / v < 0 ? "-0" : "0";
        }
        BigDecimal d = new BigDecimal(v).round(new MathContext(precision, RoundingMode.HALF_EVEN));
        int exponent = d.precision() - d.scale() - 1;
        if (exponent >= -4 && exponent < precision) {
            return strip(d.setScale(Math.max(0, precision - 1 - exponent), RoundingMode.HALF_EVEN).toPlainString());
        }
        String digits = d.unscaledValue().abs().toString();
        String mantissa = strip(digits.charAt(0) + (digits.length() > 1 ? "." + digits.substring(1) : ""));
        String e = Integer.toString(Math.abs(exponent));
        return (d.signum() < 0 ? "-" : "") + mantissa + (exponent < 0 ? "e-" : "e+") + (e.length() < 2 ? "0" + e : e);
    }

    private static String strip(String s) {
        if (s.indexOf('.') < 0) {
            return s;
        }
        int end = s.length();
        while (s.charAt(end - 1) == '0') {
            end--;
        }
        if (s.charAt(end - 1) == '.') {
            end--;
        }
        return s.substring(0, end);
    }
}
