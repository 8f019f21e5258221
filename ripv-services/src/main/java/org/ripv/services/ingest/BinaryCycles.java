package org.ripv.services.ingest;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A binary file's cycles for {@link DbaIngest}, straight from the {@link SlocumBinaryReader}: no
 * DBA text in between. The header reads as dbd2asc's would ({@code filename} is the binary
 * header's {@code full_filename}); positions come out in decimal degrees and "no fix" or
 * impossible ones as NaN, counted, as {@link DbaReader} gives them. A 4-byte float is stored as the
 * shortest decimal that is that float ({@code 0.1f} as 0.1, not 0.10000000149011612): the value
 * the glider sent, without the noise of widening it.
 */
public final class BinaryCycles extends ColumnCycles {
    private final SlocumBinaryReader reader;
    private final byte[] sizes;

    public BinaryCycles(SlocumBinaryReader reader, String file) throws SlocumFormatException {
        super(headerOf(reader));
        this.reader = reader;
        List<Sensor> sensors = header().sensors();
        this.sizes = new byte[sensors.size()];
        for (Sensor s : sensors) {
            sizes[s.index()] = (byte) s.bytes();
        }
        if (!columns.timed()) {
            throw new SlocumFormatException(file, reader.offset(),
                    "no m_present_time or sci_m_present_time among the cycle's sensors: the cycles have no time");
        }
    }

    /** The binary header read as dbd2asc would write it: {@code filename} is {@code full_filename}. */
    private static DbaHeader headerOf(SlocumBinaryReader reader) {
        Map<String, String> tags = new LinkedHashMap<>(reader.tags());
        String full = tags.getOrDefault("full_filename", tags.get("filename"));
        if (full != null) {
            tags.put("filename", full);
        }
        List<Sensor> sensors = new ArrayList<>(reader.sensors().size());
        for (SlocumSensor s : reader.sensors()) {
            sensors.add(new Sensor(sensors.size(), s.name(), s.units(), s.bytes(), Sensor.kindOf(s.name(), s.units())));
        }
        return new DbaHeader(tags, sensors);
    }

    @Override
    public boolean next(double[] values) throws IOException, SlocumFormatException {
        if (!reader.next(values)) {
            return false;
        }
        for (int i = 0; i < values.length; i++) {
            double v = values[i];
            if (Double.isNaN(v)) {
                continue;
            }
            if (columns.isPosition(i)) {
                values[i] = columns.degrees(i, v);
            } else if (sizes[i] == 4 && Double.isFinite(v)) {
                values[i] = Double.parseDouble(Float.toString((float) v));
            }
        }
        counted();
        return true;
    }

    @Override
    public String leftOut() {
        return reader.leftOut();
    }

    @Override
    public void close() throws IOException {
        reader.close();
    }
}
