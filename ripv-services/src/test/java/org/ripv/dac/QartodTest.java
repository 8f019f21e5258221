package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@link Qartod} and {@link QcConfig} against the flags ioos_qc returned (../shared/data/dac/qartod-vectors.json), every case, flag for flag. */
class QartodTest {
    static final Path VECTORS = Path.of("..", "..", "shared", "data", "dac", "qartod-vectors.json");

    static Path vectors() {
        Path p = Path.of(System.getProperty("user.dir")).resolve("../../shared/data/dac/qartod-vectors.json").normalize();
        assumeTrue(Files.exists(p), "the shared QARTOD vectors are not at " + p);
        return p;
    }

    static double[] doubles(JsonNode a) {
        double[] d = new double[a.size()];
        for (int i = 0; i < d.length; i++) {
            d[i] = a.get(i).isNull() ? Double.NaN : a.get(i).asDouble();
        }
        return d;
    }

    static byte[] bytes(JsonNode a) {
        byte[] b = new byte[a.size()];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) a.get(i).asInt();
        }
        return b;
    }

    @Test
    void everyCaseGivesIoosQcsFlags() throws IOException {
        JsonNode cases = new ObjectMapper().readTree(vectors().toFile()).get("cases");
        List<byte[]> forAggregate = new ArrayList<>();
        int checked = 0;
        for (JsonNode c : cases) {
            String test = c.get("test").asText();
            byte[] want = bytes(c.get("flags"));
            if (test.startsWith("aggregate")) {
                assertThat(Qartod.aggregate(forAggregate, want.length)).as(test).containsExactly(want);
                checked++;
                continue;
            }
            double[] in = doubles(c.get("input"));
            double[] t = c.get("time").isNull() ? null : doubles(c.get("time"));
            JsonNode p = c.get("params");
            byte[] got = switch (test) {
                case "gross_range_test" -> Qartod.grossRange(in, doubles(p.get("fail_span")),
                        p.has("suspect_span") ? doubles(p.get("suspect_span")) : null);
                case "spike_test" -> Qartod.spike(in, p.get("suspect_threshold").asDouble(), p.get("fail_threshold").asDouble(),
                        p.has("method") ? p.get("method").asText() : null);
                case "rate_of_change_test" -> Qartod.rateOfChange(in, t, p.get("threshold").asDouble());
                case "flat_line_test" -> Qartod.flatLine(in, t, p.get("suspect_threshold").asDouble(),
                        p.get("fail_threshold").asDouble(), p.get("tolerance").asDouble());
                default -> throw new AssertionError("unknown case " + test);
            };
            assertThat(got).as(test + " " + p).containsExactly(want);
            if (in.length == 60 && !(p.has("method"))) {
                forAggregate.add(got);
            }
            checked++;
        }
        assertThat(checked).isEqualTo(cases.size());
        assertThat(forAggregate).hasSize(4);
    }

    @Test
    void theYamlConfigurationRunsTheSameTests(@TempDir Path dir) throws Exception {
        JsonNode cases = new ObjectMapper().readTree(vectors().toFile()).get("cases");
        Path yml = dir.resolve("qc.yml");
        Files.writeString(yml, """
                temperature:
                  qartod:
                    flat_line_test: {tolerance: 0.0001, suspect_threshold: 30, fail_threshold: 60}
                    gross_range_test:
                      suspect_span: [14.9, 16.0]
                      fail_span: [-2.5, 40.0]
                    spike_test: {suspect_threshold: 0.05, fail_threshold: 0.5}
                    rate_of_change_test: {threshold: 0.01}
                """);
        QcConfig qc = QcConfig.read(yml);
        JsonNode c = cases.get(3);
        Map<QcConfig.Test, byte[]> flags = QcConfig.run(qc.tests().get("temperature"), doubles(c.get("input")), doubles(c.get("time")));
        assertThat(flags.keySet()).extracting(QcConfig.Test::shortName).containsExactly("gross_range", "spike", "rate_of_change", "flat_line");
        assertThat(Qartod.aggregate(List.copyOf(flags.values()), 60)).containsExactly(bytes(cases.get(5).get("flags")));
    }

    @Test
    void badConfigurationsAreRefusedByName(@TempDir Path dir) throws IOException {
        Path yml = dir.resolve("qc.yml");
        Files.writeString(yml, "temperature:\n  qartod:\n    gross_range_test: {fail_span: [0, 1], suspect_span: [-1, 2]}\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("suspect_span must fall within the fail_span");
        Files.writeString(yml, "temperature:\n  qartod:\n    climatology_test: {}\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("unknown test 'climatology_test'");
        Files.writeString(yml, "temprature:\n  qartod: {}\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("unknown variable 'temprature'");
        Files.writeString(yml, "temperature:\n  qartod:\n    spike_test: {suspect_threshold: high, fail_threshold: 1}\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("suspect_threshold must be a number");
        Files.writeString(yml, "temperature:\n  qartod:\n    rate_of_change_test: {}\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("threshold must be a number (missing)");
        Files.writeString(yml, "- just\n- a list\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).hasMessageContaining("expected variables");
        Files.writeString(yml, "temperature: [unclosed\n");
        assertThatThrownBy(() -> QcConfig.read(yml)).isInstanceOf(DacException.class).hasMessageContaining("not ioos_qc YAML");
    }
}
