package org.ripv.server.session;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.SerializableString;
import com.fasterxml.jackson.core.io.CharacterEscapes;
import com.fasterxml.jackson.core.io.SerializedString;
import com.fasterxml.jackson.core.json.JsonWriteFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Flat JSON objects (strings, numbers, booleans, null) for the transcript, vehicle-state and
 * subscription files, one object per line, through Jackson. Written as RIPV always wrote them:
 * every control character, DEL, the C1 controls and U+2028/2029 escaped (lower-case hex), so one
 * object is always one line that is safe on a terminal; NaN and infinities become null. Read
 * strictly, the line treated as hostile: anything but one flat object is an
 * {@link IllegalArgumentException}.
 */
public final class Json {
    private static final ObjectMapper MAPPER = mapper();

    private Json() {}

    private static ObjectMapper mapper() {
        JsonFactory f = JsonFactory.builder().disable(JsonWriteFeature.WRITE_HEX_UPPER_CASE).build();
        f.setCharacterEscapes(new LineSafe());
        return new ObjectMapper(f).enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS);
    }

    /** JSON's own escapes, plus DEL, C1 and the Unicode line separators: JSON lines reach terminals. */
    private static final class LineSafe extends CharacterEscapes {
        private static final long serialVersionUID = 1L;
        private final int[] codes = standardAsciiEscapesForJSON();

        LineSafe() {
            codes['\b'] = ESCAPE_STANDARD; // as \u0008, not \b: the files have always said it so
            codes['\f'] = ESCAPE_STANDARD;
            codes[0x7f] = ESCAPE_STANDARD;
        }

        @Override
        public int[] getEscapeCodesForAscii() {
            return codes;
        }

        @Override
        public SerializableString getEscapeSequence(int ch) {
            return ch >= 0x80 && ch <= 0x9f || ch == 0x2028 || ch == 0x2029
                    ? new SerializedString(String.format("\\u%04x", ch)) : null;
        }
    }

    /** Writes a flat object; values are String, Number, Boolean or null. */
    public static String write(Map<String, ?> fields) {
        Map<String, Object> finite = new LinkedHashMap<>();
        fields.forEach((k, v) -> finite.put(k, v instanceof Double d && !Double.isFinite(d)
                || v instanceof Float f && !Float.isFinite(f) ? null : v));
        try {
            return MAPPER.writeValueAsString(finite);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("cannot write " + fields.keySet() + " as JSON: " + e.getOriginalMessage(), e);
        }
    }

    /** Reads a flat object: values come back as String, Long (or Double), Boolean or null. */
    public static Map<String, Object> parse(String line) {
        JsonNode root;
        try {
            root = MAPPER.readTree(line);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException(e.getOriginalMessage(), e);
        }
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("not a JSON object");
        }
        Map<String, Object> out = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = root.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            out.put(e.getKey(), value(e.getKey(), e.getValue()));
        }
        return out;
    }

    private static Object value(String key, JsonNode v) {
        if (v.isNull()) {
            return null;
        }
        if (v.isTextual()) {
            return v.textValue();
        }
        if (v.isBoolean()) {
            return v.booleanValue();
        }
        if (v.isIntegralNumber()) {
            return v.canConvertToLong() ? (Object) v.longValue() : (Object) v.doubleValue();
        }
        if (v.isNumber()) {
            return v.doubleValue();
        }
        throw new IllegalArgumentException("'" + key + "' is not a string, number, boolean or null");
    }
}
