package org.ripv.dac;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The QC configuration in ioos_qc's own YAML: variable → {@code qartod} → test → parameters, e.g.
 * <pre>
 * temperature:
 *   qartod:
 *     gross_range_test: {suspect_span: [0, 30], fail_span: [-2.5, 40]}
 *     spike_test: {suspect_threshold: 0.5, fail_threshold: 1.5}
 *     rate_of_change_test: {threshold: 0.1}
 *     flat_line_test: {tolerance: 0.001, suspect_threshold: 300, fail_threshold: 900}
 * </pre>
 * (ioos_qc's {@code streams:} wrapper is accepted too). Variables are the DAC file's names; a
 * test or a parameter RIPV does not know, or a value of the wrong type, is refused by name.
 */
public final class QcConfig {
    /** The profile variables QC may be configured for. */
    public static final Set<String> VARIABLES = Set.of("pressure", "depth", "temperature", "conductivity", "salinity", "density");
    /** The tests, in the order their flags are written. */
    public static final List<String> TESTS = List.of("gross_range_test", "spike_test", "rate_of_change_test", "flat_line_test");

    /** One configured test: its name and parameters as given. */
    public record Test(String name, Map<String, Object> params, String json) {
        /** The flag variable's test part: {@code gross_range} for {@code gross_range_test}. */
        public String shortName() {
            return name.substring(0, name.length() - "_test".length());
        }
    }

    private final Map<String, List<Test>> tests;

    private QcConfig(Map<String, List<Test>> tests) {
        this.tests = tests;
    }

    /** No QC at all: every {@code _qc} variable says "no QC performed". */
    public static QcConfig none() {
        return new QcConfig(Map.of());
    }

    public Map<String, List<Test>> tests() {
        return tests;
    }

    public static QcConfig read(Path file) throws DacException {
        JsonNode root;
        try {
            if (Files.size(file) > 1 << 20) {
                throw new DacException(file + ": a QC configuration over 1 MiB is not one");
            }
            root = new ObjectMapper(new YAMLFactory()).readTree(file.toFile());
        } catch (IOException e) {
            throw new DacException(file + ": not ioos_qc YAML: " + e.getMessage().lines().findFirst().orElse(""), e);
        }
        return parse(root, file.toString());
    }

    public static QcConfig parse(JsonNode root, String source) throws DacException {
        if (root == null || !root.isObject()) {
            throw new DacException(source + ": expected variables with a 'qartod' section each (ioos_qc's YAML), found " + kind(root));
        }
        if (root.has("streams")) {
            root = root.get("streams");
        }
        Map<String, List<Test>> out = new LinkedHashMap<>();
        ObjectMapper json = new ObjectMapper();
        for (Iterator<Map.Entry<String, JsonNode>> it = root.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> v = it.next();
            String var = v.getKey();
            if (!VARIABLES.contains(var)) {
                throw new DacException(source + ": unknown variable '" + var + "': QC applies to " + String.join(", ", VARIABLES.stream().sorted().toList()));
            }
            JsonNode q = v.getValue() == null ? null : v.getValue().get("qartod");
            if (q == null || !q.isObject()) {
                throw new DacException(source + ": " + var + " has no 'qartod' section of tests");
            }
            List<Test> list = new ArrayList<>();
            for (Iterator<Map.Entry<String, JsonNode>> ts = q.fields(); ts.hasNext(); ) {
                Map.Entry<String, JsonNode> t = ts.next();
                String name = t.getKey();
                if (!TESTS.contains(name)) {
                    throw new DacException(source + ": " + var + ": unknown test '" + name + "': RIPV runs " + String.join(", ", TESTS));
                }
                JsonNode p = t.getValue();
                if (p == null || !p.isObject()) {
                    throw new DacException(source + ": " + var + "." + name + ": parameters expected, found " + kind(p));
                }
                Map<String, Object> params = params(p, source + ": " + var + "." + name);
                check(name, params, source + ": " + var + "." + name);
                try {
                    list.add(new Test(name, params, json.writeValueAsString(p)));
                } catch (IOException e) {
                    throw new DacException(source + ": " + e.getMessage(), e);
                }
            }
            list.sort((a, b) -> Integer.compare(TESTS.indexOf(a.name()), TESTS.indexOf(b.name())));
            out.put(var, List.copyOf(list));
        }
        return new QcConfig(out);
    }

    private static Map<String, Object> params(JsonNode p, String where) throws DacException {
        Map<String, Object> m = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = p.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            JsonNode n = e.getValue();
            if (n.isNumber()) {
                m.put(e.getKey(), n.asDouble());
            } else if (n.isArray() && n.size() == 2 && n.get(0).isNumber() && n.get(1).isNumber()) {
                m.put(e.getKey(), new double[] {n.get(0).asDouble(), n.get(1).asDouble()});
            } else if (n.isTextual()) {
                m.put(e.getKey(), n.asText());
            } else {
                throw new DacException(where + ": " + e.getKey() + " must be a number or a pair of numbers, not " + kind(n));
            }
        }
        return m;
    }

    private static void check(String test, Map<String, Object> p, String where) throws DacException {
        switch (test) {
            case "gross_range_test" -> {
                allowed(p, where, "fail_span", "suspect_span");
                span(p, "fail_span", true, where);
                span(p, "suspect_span", false, where);
            }
            case "spike_test" -> {
                allowed(p, where, "suspect_threshold", "fail_threshold", "method");
                number(p, "suspect_threshold", where);
                number(p, "fail_threshold", where);
                Object m = p.get("method");
                if (m != null && !"average".equals(m) && !"differential".equals(m)) {
                    throw new DacException(where + ": method must be average or differential, not " + m);
                }
            }
            case "rate_of_change_test" -> {
                allowed(p, where, "threshold");
                number(p, "threshold", where);
            }
            default -> {
                allowed(p, where, "tolerance", "suspect_threshold", "fail_threshold");
                number(p, "tolerance", where);
                number(p, "suspect_threshold", where);
                number(p, "fail_threshold", where);
            }
        }
        if (test.equals("gross_range_test") && p.get("suspect_span") instanceof double[] s) {
            double[] f = (double[]) p.get("fail_span");
            if (Math.min(s[0], s[1]) < Math.min(f[0], f[1]) || Math.max(s[0], s[1]) > Math.max(f[0], f[1])) {
                throw new DacException(where + ": the suspect_span must fall within the fail_span");
            }
        }
    }

    private static void allowed(Map<String, Object> p, String where, String... names) throws DacException {
        for (String k : p.keySet()) {
            if (!List.of(names).contains(k)) {
                throw new DacException(where + ": unknown parameter '" + k + "': it takes " + String.join(", ", names));
            }
        }
    }

    private static void number(Map<String, Object> p, String key, String where) throws DacException {
        if (!(p.get(key) instanceof Double)) {
            throw new DacException(where + ": " + key + " must be a number" + (p.containsKey(key) ? "" : " (missing)"));
        }
    }

    private static void span(Map<String, Object> p, String key, boolean required, String where) throws DacException {
        if (!p.containsKey(key) && !required) {
            return;
        }
        if (!(p.get(key) instanceof double[])) {
            throw new DacException(where + ": " + key + " must be a pair of numbers [low, high]" + (p.containsKey(key) ? "" : " (missing)"));
        }
    }

    static String kind(JsonNode n) {
        if (n == null || n.isNull() || n.isMissingNode()) {
            return "nothing";
        }
        return n.getNodeType().name().toLowerCase(java.util.Locale.ROOT) + " " + abbreviate(n.toString());
    }

    private static String abbreviate(String s) {
        return s.length() > 40 ? s.substring(0, 40) + "…" : s;
    }

    /** Runs one variable's tests on a profile's values in time order: test name → flags. */
    public static Map<Test, byte[]> run(List<Test> tests, double[] values, double[] time) {
        Map<Test, byte[]> out = new LinkedHashMap<>();
        for (Test t : tests) {
            Map<String, Object> p = t.params();
            byte[] f = switch (t.name()) {
                case "gross_range_test" -> Qartod.grossRange(values, (double[]) p.get("fail_span"), (double[]) p.get("suspect_span"));
                case "spike_test" -> Qartod.spike(values, (Double) p.get("suspect_threshold"), (Double) p.get("fail_threshold"), (String) p.get("method"));
                case "rate_of_change_test" -> Qartod.rateOfChange(values, time, (Double) p.get("threshold"));
                default -> Qartod.flatLine(values, time, (Double) p.get("suspect_threshold"), (Double) p.get("fail_threshold"), (Double) p.get("tolerance"));
            };
            out.put(t, f);
        }
        return out;
    }
}
