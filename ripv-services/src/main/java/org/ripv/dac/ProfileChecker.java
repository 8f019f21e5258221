package org.ripv.dac;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ucar.ma2.Array;
import ucar.nc2.Attribute;
import ucar.nc2.Dimension;
import ucar.nc2.NetcdfFile;
import ucar.nc2.Variable;

/**
 * Checks a profile file as the DAC's checker (cc-plugin-glider) does before a file is sent:
 * the template's dimensions, every variable with its type and dimensions, every attribute
 * present and not empty, the global attributes, {@code valid_min/valid_max} of the variable's
 * own type, {@code _qc} variables with {@code flag_values} and {@code flag_meanings} that agree,
 * the {@code platform} and {@code instrument_ctd} containers the variables point to, time
 * strictly increasing, a depth span within the profile, and positions within their valid
 * ranges. Values of the other variables outside their valid range are warnings, not failures
 * (a glider at the surface reads fresh air as conductivity).
 */
public final class ProfileChecker {
    /** What the check found: failures (the file is not to be sent) and warnings. */
    public record Report(Path file, List<String> failures, List<String> warnings) {
        public boolean passed() {
            return failures.isEmpty();
        }
    }

    private final CdlTemplate template = CdlTemplate.v2();

    public Report check(Path file) throws IOException {
        List<String> fail = new ArrayList<>();
        List<String> warn = new ArrayList<>();
        try (NetcdfFile file0 = NetcdfFile.open(file.toString())) {
            // NetCDF-Java's find* escape names through its HTTP module, which RIPV leaves out: look names up here.
            Nc nc = new Nc(file0);
            Dimension time = nc.dims().get("time");
            if (time == null) {
                fail.add("no dimension time");
            }
            Dimension str = nc.dims().get("traj_strlen");
            if (str == null || str.getLength() != 20) {
                fail.add("dimension traj_strlen must be 20");
            }
            for (CdlTemplate.Var tv : template.variables()) {
                Variable v = nc.vars().get(tv.name());
                if (v == null) {
                    fail.add("variable " + tv.name() + " is missing");
                    continue;
                }
                String type = v.getDataType().toString();
                if (!type.equals(tv.type())) {
                    fail.add(tv.name() + " is " + type + ", the template says " + tv.type());
                }
                List<String> dims = v.getDimensions().stream().map(Dimension::getShortName).toList();
                if (!dims.equals(tv.dims())) {
                    fail.add(tv.name() + " has dimensions " + dims + ", the template says " + tv.dims());
                }
                for (String a : tv.attributes().keySet()) {
                    Attribute at = v.findAttribute(a);
                    if (at == null) {
                        fail.add(tv.name() + ":" + a + " is missing");
                    } else if (at.isString() && at.getStringValue().isEmpty()) {
                        fail.add(tv.name() + ":" + a + " is empty");
                    }
                }
                for (String a : List.of("valid_min", "valid_max", "_FillValue")) {
                    Attribute at = v.findAttribute(a);
                    if (at != null && at.getDataType() != v.getDataType()) {
                        fail.add(tv.name() + ":" + a + " is " + at.getDataType() + ", not the variable's " + v.getDataType());
                    }
                }
                for (String ref : List.of("platform", "instrument")) {
                    Attribute at = v.findAttribute(ref);
                    if (at != null && at.isString() && nc.vars().get(at.getStringValue()) == null) {
                        fail.add(tv.name() + ":" + ref + " names " + at.getStringValue() + ", which the file lacks");
                    }
                }
                if (tv.name().endsWith("_qc") || tv.name().startsWith("qartod_")) {
                    flags(v, fail);
                }
            }
            for (Variable v : nc.file().getVariables()) {
                if (v.getShortName().startsWith("qartod_")) {
                    flags(v, fail);
                }
            }
            for (String g : template.globals().keySet()) {
                Attribute at = nc.globals().get(g);
                if (at == null) {
                    fail.add("global attribute " + g + " is missing");
                } else if (at.isString() && at.getStringValue().isBlank()) {
                    fail.add("global attribute " + g + " is empty");
                }
            }
            if (fail.isEmpty()) {
                values(nc, fail, warn);
            }
        }
        return new Report(file, List.copyOf(fail), List.copyOf(warn));
    }

    private static void flags(Variable v, List<String> fail) {
        Attribute values = v.findAttribute("flag_values");
        Attribute meanings = v.findAttribute("flag_meanings");
        if (values == null || meanings == null) {
            fail.add(v.getShortName() + " needs flag_values and flag_meanings");
        } else if (words(meanings.getStringValue()) != values.getLength()) {
            fail.add(v.getShortName() + ": " + values.getLength() + " flag_values but "
                    + words(meanings.getStringValue()) + " flag_meanings");
        } else if (values.getDataType() != v.getDataType()) {
            fail.add(v.getShortName() + ":flag_values is " + values.getDataType() + ", not the variable's " + v.getDataType());
        }
    }

    /** The words of a space-separated list, as {@code trim().split("\\s+").length} counts them (1 for an empty one), without a regex per flag variable. */
    static int words(String list) {
        String s = list.trim();
        int n = 0;
        boolean inWord = false;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            boolean space = c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
            if (!space && !inWord) {
                n++;
            }
            inWord = !space;
        }
        return Math.max(n, 1);
    }

    private void values(Nc nc, List<String> fail, List<String> warn) throws IOException {
        double[] t = doubles(nc.vars().get("time"));
        if (t.length == 0) {
            fail.add("no samples (time has length 0)");
            return;
        }
        for (int i = 1; i < t.length; i++) {
            if (!(t[i] > t[i - 1])) {
                fail.add("time is not strictly increasing at sample " + i + " (" + t[i] + " after " + t[i - 1] + ")");
                break;
            }
        }
        double[] depth = doubles(nc.vars().get("depth"));
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double d : depth) {
            if (d != ProfileWriter.FILL) {
                lo = Math.min(lo, d);
                hi = Math.max(hi, d);
            }
        }
        if (!(hi - lo > 0)) {
            fail.add("depth has no span within the profile (" + (lo > hi ? "no depth at all" : lo + " m throughout") + ")");
        }
        for (CdlTemplate.Var tv : template.variables()) {
            Map<String, Object> a = tv.attributes();
            if (!tv.type().equals("double") || !a.containsKey("valid_min")) {
                continue;
            }
            double min = number(a.get("valid_min"));
            double max = number(a.get("valid_max"));
            int out = 0;
            double first = Double.NaN;
            for (double x : doubles(nc.vars().get(tv.name()))) {
                if (x != ProfileWriter.FILL && (x < min || x > max)) {
                    out++;
                    first = Double.isNaN(first) ? x : first;
                }
            }
            if (out > 0) {
                String msg = tv.name() + ": " + out + " value" + (out == 1 ? "" : "s") + " outside [" + min + ", " + max + "], e.g. " + first;
                if (List.of("lat", "lon", "profile_lat", "profile_lon", "lat_uv", "lon_uv").contains(tv.name())) {
                    fail.add(msg);
                } else {
                    warn.add(msg);
                }
            }
        }
    }

    private static double number(Object o) {
        if (o instanceof double[] d) {
            return d[0];
        }
        return ((int[]) o)[0];
    }

    private static double[] doubles(Variable v) throws IOException {
        Array a = v.read();
        if (a.getElementType() == double.class) {
            return (double[]) a.get1DJavaArray(double.class); // the values as read, no copy
        }
        double[] d = new double[(int) a.getSize()];
        for (int i = 0; i < d.length; i++) {
            d[i] = a.getDouble(i);
        }
        return d;
    }

    /** A file's variables, dimensions and global attributes by short name. */
    private record Nc(NetcdfFile file, Map<String, Variable> vars, Map<String, Dimension> dims, Map<String, Attribute> globals) {
        Nc(NetcdfFile file) {
            this(file, new HashMap<>(), new HashMap<>(), new HashMap<>());
            file.getVariables().forEach(v -> vars.put(v.getShortName(), v));
            file.getDimensions().forEach(d -> dims.put(d.getShortName(), d));
            file.getGlobalAttributes().forEach(a -> globals.put(a.getShortName(), a));
        }
    }
}
