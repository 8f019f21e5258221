package org.ripv.services.ingest;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What a DBA file's header and label lines say: the {@code key: value} tags in file order, and
 * the sensors (columns).
 *
 * @param tags    the header tags ({@code filename}, {@code mission_name}, {@code fileopen_time}, ...)
 * @param sensors the columns in order
 */
public record DbaHeader(Map<String, String> tags, List<Sensor> sensors) {
    public DbaHeader {
        tags = Collections.unmodifiableMap(new LinkedHashMap<>(tags));
        sensors = List.copyOf(sensors);
    }

    /** A tag's value, or null. */
    public String tag(String key) {
        return tags.get(key);
    }

    /** The file's own name ({@code filename}, e.g. {@code cp_388-2016-012-0-0}), or null. */
    public String filename() {
        return tags.get("filename");
    }

    /**
     * The glider's name: what {@code filename} has before its first '-' ({@code cp_388} of
     * {@code cp_388-2016-012-0-0}), or null when the header has no usable filename.
     */
    public String vehicle() {
        String f = filename();
        if (f == null || f.isBlank()) {
            return null;
        }
        int dash = f.indexOf('-');
        String v = dash > 0 ? f.substring(0, dash) : f;
        return v.length() > 64 ? v.substring(0, 64) : v;
    }

    /** The column of a sensor, or -1. */
    public int column(String name) {
        for (Sensor s : sensors) {
            if (s.name().equals(name)) {
                return s.index();
            }
        }
        return -1;
    }
}
