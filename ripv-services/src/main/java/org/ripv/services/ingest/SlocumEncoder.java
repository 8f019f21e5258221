package org.ripv.services.ingest;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes the plain binary format {@link SlocumBinaryReader} reads (big-endian, the sensor list in
 * the file, encoding version 5): for tests and benchmarks that need files of a given size. Each
 * cycle's states are chosen as the glider does: 0 for NaN, 1 for the value before, 2 otherwise.
 * The first cycle written is the one readers skip; {@link #start} writes an empty one.
 */
public final class SlocumEncoder {
    private final DataOutputStream out;
    private final byte[] sizes;
    private final double[] last;
    private final byte[] states;

    private SlocumEncoder(OutputStream out, List<SlocumSensor> sensors) {
        this.out = new DataOutputStream(out);
        this.sizes = new byte[sensors.size()];
        for (int i = 0; i < sizes.length; i++) {
            sizes[i] = (byte) sensors.get(i).bytes();
        }
        this.last = new double[sizes.length];
        Arrays.fill(last, Double.NaN);
        this.states = new byte[(sizes.length + 3) / 4];
    }

    /** Writes the header (with {@code tags} such as full_filename, the8x3_filename, filename_extension), list and known bytes. */
    public static SlocumEncoder start(OutputStream out, Map<String, String> tags, List<SlocumSensor> sensors) throws IOException {
        StringBuilder h = new StringBuilder();
        h.append("dbd_label:    ").append(SlocumBinaryReader.LABEL).append('\n')
                .append("encoding_ver:    ").append(SlocumBinaryReader.ENCODING).append('\n')
                .append("num_ascii_tags:    ").append(9 + tags.size()).append('\n')
                .append("all_sensors:    F\n");
        tags.forEach((k, v) -> h.append(k).append(":    ").append(v).append('\n'));
        h.append("total_num_sensors:    ").append(sensors.size()).append('\n')
                .append("sensors_per_cycle:    ").append(sensors.size()).append('\n')
                .append("state_bytes_per_cycle:    ").append((sensors.size() + 3) / 4).append('\n')
                ;
        List<String> list = new ArrayList<>();
        for (int i = 0; i < sensors.size(); i++) {
            SlocumSensor s = sensors.get(i);
            list.add(String.format(Locale.ROOT, "s: T %4d %4d %d %s %s", i, i, s.bytes(), s.name(), s.units()));
        }
        h.append("sensor_list_crc:    ").append(SensorListCache.crcOf(list)).append('\n') // the firmware's CRC of the list
                .append("sensor_list_factored:    0\n");
        list.forEach(l -> h.append(l).append('\n'));
        out.write(h.toString().getBytes(StandardCharsets.US_ASCII));
        SlocumEncoder e = new SlocumEncoder(out, sensors);
        e.out.writeByte('s');
        e.out.writeByte('a');
        e.out.writeShort(0x1234);
        e.out.writeFloat(123.456f);
        e.out.writeDouble(123456789.12345);
        double[] none = new double[sensors.size()];
        Arrays.fill(none, Double.NaN);
        e.cycle(none);
        return e;
    }

    /** One cycle. */
    public void cycle(double[] values) throws IOException {
        Arrays.fill(states, (byte) 0);
        for (int i = 0; i < sizes.length; i++) {
            double v = values[i];
            int state = Double.isNaN(v) ? 0 : Double.compare(v, last[i]) == 0 ? 1 : 2;
            states[i >> 2] |= (byte) (state << (6 - ((i & 3) << 1)));
        }
        out.writeByte('d');
        out.write(states);
        for (int i = 0; i < sizes.length; i++) {
            double v = values[i];
            if (Double.isNaN(v) || Double.compare(v, last[i]) == 0) {
                continue;
            }
            last[i] = v;
            switch (sizes[i]) {
                case 1 -> out.writeByte((int) v);
                case 2 -> out.writeShort((int) v);
                case 4 -> out.writeFloat((float) v);
                default -> out.writeDouble(v);
            }
        }
    }

    /** Changes a cycle of {@link #recode} in place: the row has the file's sensors, then the added ones (NaN). */
    @FunctionalInterface
    public interface Edit {
        void apply(double[] row, long cycle);
    }

    /**
     * Another file of the same segment, as a {@code .dbd} is to its {@code .sbd}: the same header
     * tags but {@code extension}, the same cycles (each changed by {@code edit}), with the sensors
     * {@code added} after the file's own, the sensor list in the file.
     */
    public static byte[] recode(byte[] file, SensorListCache cache, String extension, List<SlocumSensor> added, Edit edit)
            throws IOException, SlocumFormatException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(file.length * 2);
        try (SlocumBinaryReader r = new SlocumBinaryReader(new ByteArrayInputStream(file), "recoded", cache)) {
            List<SlocumSensor> sensors = new ArrayList<>(r.sensors());
            sensors.addAll(added);
            Map<String, String> tags = new LinkedHashMap<>();
            for (String k : List.of("the8x3_filename", "full_filename", "filename_extension", "mission_name", "fileopen_time")) {
                tags.put(k, k.equals("filename_extension") ? extension : r.tags().getOrDefault(k, ""));
            }
            SlocumEncoder e = start(out, tags, sensors);
            double[] row = new double[r.sensors().size()];
            double[] wide = new double[sensors.size()];
            long n = 0;
            while (r.next(row)) {
                Arrays.fill(wide, Double.NaN);
                System.arraycopy(row, 0, wide, 0, row.length);
                edit.apply(wide, ++n);
                e.cycle(wide);
            }
            e.end();
        }
        return out.toByteArray();
    }

    /** The end tag. */
    public void end() throws IOException {
        out.writeByte('X');
        out.flush();
    }
}
