package org.ripv.dac;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The DAC's file template, {@code IOOS_Glider_NetCDF_v2.0.cdl} (shipped beside this class, as the
 * DAC's checker cc-plugin-glider ships it; Apache-2.0), read from its CDL: its variables in
 * order, with type, dimensions and attributes, and its global attributes. The writer makes a
 * file variable for variable and attribute for attribute from it, and the checker checks a file
 * against it, so both follow the one template.
 */
public final class CdlTemplate {
    /** An attribute value: a String, or an array of {@code byte}, {@code int} or {@code double}. */
    public record Var(String name, String type, List<String> dims, Map<String, Object> attributes) {
    }

    private final List<Var> variables;
    private final Map<String, Object> globals;

    private CdlTemplate(List<Var> variables, Map<String, Object> globals) {
        this.variables = variables;
        this.globals = globals;
    }

    public List<Var> variables() {
        return variables;
    }

    public Var variable(String name) {
        return variables.stream().filter(v -> v.name().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no variable " + name + " in the template"));
    }

    public Map<String, Object> globals() {
        return globals;
    }

    private static volatile CdlTemplate v2;

    /** The IOOS_Glider_NetCDF_v2.0 template. */
    public static CdlTemplate v2() {
        if (v2 == null) {
            try (InputStream in = CdlTemplate.class.getResourceAsStream("IOOS_Glider_NetCDF_v2.0.cdl")) {
                v2 = parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new IllegalStateException("the DAC template is missing from the jar", e);
            }
        }
        return v2;
    }

    private static final Pattern DECL = Pattern.compile("^\\s*(char|byte|short|int|float|double)\\s+(\\w+)\\s*(?:\\(([^)]*)\\))?\\s*;\\s*$");
    private static final Pattern ATTR = Pattern.compile("^\\s*(\\w*):(\\w+)\\s*=\\s*(.*?)\\s*;\\s*$");

    static CdlTemplate parse(String cdl) {
        List<Var> vars = new ArrayList<>();
        Map<String, Object> globals = new LinkedHashMap<>();
        Map<String, Var> byName = new LinkedHashMap<>();
        for (String line : cdl.split("\n")) {
            Matcher d = DECL.matcher(line);
            if (d.matches()) {
                List<String> dims = d.group(3) == null ? List.of() : List.of(d.group(3).trim().split("\\s*,\\s*"));
                Var v = new Var(d.group(2), d.group(1), dims, new LinkedHashMap<>());
                vars.add(v);
                byName.put(v.name(), v);
                continue;
            }
            Matcher a = ATTR.matcher(line);
            if (a.matches()) {
                Object value = value(a.group(3));
                if (a.group(1).isEmpty()) {
                    globals.put(a.group(2), value);
                } else {
                    byName.get(a.group(1)).attributes().put(a.group(2), value);
                }
            }
        }
        return new CdlTemplate(List.copyOf(vars), globals);
    }

    private static Object value(String text) {
        if (text.startsWith("\"")) {
            return text.substring(1, text.length() - 1).replace("\\'", "'").replace("\\\"", "\"");
        }
        String[] parts = text.split("\\s*,\\s*");
        if (parts[0].endsWith("b")) {
            byte[] b = new byte[parts.length];
            for (int i = 0; i < parts.length; i++) {
                b[i] = Byte.parseByte(parts[i].substring(0, parts[i].length() - 1));
            }
            return b;
        }
        if (text.contains(".") || text.contains("e")) {
            double[] d = new double[parts.length];
            for (int i = 0; i < parts.length; i++) {
                d[i] = Double.parseDouble(parts[i]);
            }
            return d;
        }
        int[] n = new int[parts.length];
        for (int i = 0; i < parts.length; i++) {
            n[i] = Integer.parseInt(parts[i]);
        }
        return n;
    }
}
