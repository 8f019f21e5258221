package org.ripv.dac;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A deployment's metadata, keyed by the template's own names: {@code global} (the file's global
 * attributes), {@code platform} and {@code instrument_ctd} (the containers' attributes), and
 * optionally {@code trajectory} (the deployment's name, at most 20 characters; by default the
 * glider's name). Every global attribute the template lists must be given, a non-empty string,
 * except those the writer sets itself ({@link #COMPUTED}); the containers need the attributes
 * that describe the glider and its CTD. Anything missing, empty or of another type is refused
 * with the key and what was found.
 */
public final class Metadata {
    /** Global attributes the writer sets: the conventions and format of the template, and the dates of the file. */
    public static final Set<String> COMPUTED = Set.of("Conventions", "Metadata_Conventions", "format_version",
            "date_created", "date_modified", "standard_name_vocabulary");
    public static final List<String> PLATFORM = List.of("id", "long_name", "wmo_id", "comment");
    public static final List<String> INSTRUMENT_CTD = List.of("make_model", "serial_number", "calibration_date",
            "factory_calibrated", "calibration_report", "long_name", "comment");

    private final Map<String, String> global;
    private final Map<String, String> platform;
    private final Map<String, String> instrumentCtd;
    private final String trajectory;

    private Metadata(Map<String, String> global, Map<String, String> platform, Map<String, String> instrumentCtd, String trajectory) {
        this.global = global;
        this.platform = platform;
        this.instrumentCtd = instrumentCtd;
        this.trajectory = trajectory;
    }

    public Map<String, String> global() {
        return global;
    }

    public Map<String, String> platform() {
        return platform;
    }

    public Map<String, String> instrumentCtd() {
        return instrumentCtd;
    }

    /** The deployment's name, or null for the glider's own. */
    public String trajectory() {
        return trajectory;
    }

    public static Metadata read(Path file) throws DacException {
        JsonNode root;
        try {
            if (Files.size(file) > 1 << 20) {
                throw new DacException(file + ": a metadata file over 1 MiB is not one");
            }
            root = new ObjectMapper().readTree(file.toFile());
        } catch (NoSuchFileException e) {
            throw new DacException(file + ": no such metadata file");
        } catch (IOException e) {
            throw new DacException(file + ": not JSON: " + e.getMessage().lines().findFirst().orElse(""), e);
        }
        return parse(root, file.getFileName().toString());
    }

    public static Metadata parse(JsonNode root, String source) throws DacException {
        List<String> problems = new ArrayList<>();
        if (root == null || !root.isObject()) {
            throw new DacException(source + ": expected an object with 'global', 'platform' and 'instrument_ctd', found " + QcConfig.kind(root));
        }
        List<String> globalsNeeded = new ArrayList<>();
        for (String k : CdlTemplate.v2().globals().keySet()) {
            if (!COMPUTED.contains(k)) {
                globalsNeeded.add(k);
            }
        }
        Map<String, String> global = section(root, "global", globalsNeeded, problems);
        Map<String, String> platform = section(root, "platform", PLATFORM, problems);
        Map<String, String> ctd = section(root, "instrument_ctd", INSTRUMENT_CTD, problems);
        String trajectory = null;
        JsonNode t = root.get("trajectory");
        if (t != null) {
            if (!t.isTextual() || t.asText().isBlank() || t.asText().length() > 20) {
                problems.add("trajectory must be a name of 1 to 20 characters, found " + QcConfig.kind(t));
            } else {
                trajectory = t.asText();
            }
        }
        for (Iterator<String> it = root.fieldNames(); it.hasNext(); ) {
            String k = it.next();
            if (!Set.of("global", "platform", "instrument_ctd", "trajectory").contains(k)) {
                problems.add("unknown key '" + k + "' (the keys are global, platform, instrument_ctd and trajectory)");
            }
        }
        if (!problems.isEmpty()) {
            throw new DacException(source + ": " + problems.size() + " problem" + (problems.size() == 1 ? "" : "s")
                    + " in the deployment metadata: " + String.join("; ", problems));
        }
        return new Metadata(global, platform, ctd, trajectory);
    }

    private static Map<String, String> section(JsonNode root, String key, List<String> needed, List<String> problems) {
        Map<String, String> out = new LinkedHashMap<>();
        JsonNode s = root.get(key);
        if (s == null || !s.isObject()) {
            problems.add("'" + key + "' must be an object of attributes, found " + QcConfig.kind(s));
            return out;
        }
        for (String n : needed) {
            JsonNode v = s.get(n);
            if (v == null || v.isNull()) {
                problems.add(key + "." + n + " is missing");
            } else if (!v.isTextual()) {
                problems.add(key + "." + n + " must be a string, found " + QcConfig.kind(v));
            } else if (v.asText().isBlank()) {
                problems.add(key + "." + n + " is empty (the DAC's checker fails empty attributes)");
            }
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = s.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            if (e.getValue().isTextual()) {
                out.put(e.getKey(), e.getValue().asText());
            } else if (e.getValue().isNumber() && !needed.contains(e.getKey())) {
                out.put(e.getKey(), e.getValue().asText());
            } else if (!needed.contains(e.getKey())) {
                problems.add(key + "." + e.getKey() + " must be a string or a number, found " + QcConfig.kind(e.getValue()));
            }
        }
        return out;
    }
}
