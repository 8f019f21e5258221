package org.ripv.dac;

import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import ucar.ma2.Array;
import ucar.ma2.ArrayChar;
import ucar.ma2.DataType;
import ucar.ma2.InvalidRangeException;
import ucar.nc2.Attribute;
import ucar.nc2.Dimension;
import ucar.nc2.NetcdfFileWriter;
import ucar.nc2.Variable;

/**
 * Writes one profile as a DAC file, NetCDF-3 classic, with Unidata's NetCDF-Java: every
 * variable and attribute of {@link CdlTemplate#v2()} in the template's order, the metadata's
 * global, {@code platform} and {@code instrument_ctd} attributes, the QARTOD flags
 * ({@code qartod_<var>_<test>_flag}, {@code qartod_<var>_primary_flag}) and the {@code <var>_qc}
 * variables. Missing values are the template's {@code _FillValue} (-999). Where the template
 * gives {@code valid_min/valid_max} of another type than its variable (pressure, depth: int on a
 * double) they are written in the variable's type, as the DAC's checker requires.
 *
 * <p>The file is written as {@code NAME.tmp} beside its place and renamed when complete: a reader
 * never sees half a file, and a failure leaves nothing behind.
 */
public final class ProfileWriter {
    static final double FILL = -999;
    static final byte QC_FILL = -127;
    private static final DateTimeFormatter NAME_TIME = DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss", Locale.ROOT).withZone(ZoneOffset.UTC);
    private static final DateTimeFormatter ISO = DateTimeFormatter.ofPattern("yyyy-MM-dd'T'HH:mm:ss'Z'", Locale.ROOT).withZone(ZoneOffset.UTC);
    static final List<String> SERIES = List.of("time", "lat", "lon", "pressure", "depth", "temperature", "conductivity", "salinity", "density");

    private final Metadata meta;
    private final QcConfig qc;
    private final CdlTemplate template = CdlTemplate.v2();
    /** Every variable's attributes as written, made once: they depend on the template, metadata and QC only. */
    private final Map<String, List<Attribute>> attributes = new LinkedHashMap<>();
    /** Each template variable's dimensions as NetCDF-Java takes them ("time", "" for a scalar), in the template's order. */
    private final List<String> dimensions = new ArrayList<>();
    /**
     * The global attributes in the order written, made once; null stands for the file's date
     * ({@code date_created}, {@code date_modified}), whose names are in {@link #globalNames}.
     */
    private final List<Attribute> fixedGlobals = new ArrayList<>();
    private final List<String> globalNames = new ArrayList<>();

    public ProfileWriter(Metadata meta, QcConfig qc) {
        this.meta = meta;
        this.qc = qc;
        for (CdlTemplate.Var tv : template.variables()) {
            List<Attribute> list = new ArrayList<>();
            for (Map.Entry<String, Object> a : tv.attributes().entrySet()) {
                Object v = value(tv, a.getKey(), a.getValue());
                if (a.getKey().equals("ancillary_variables") && qc.tests().containsKey(tv.name())) {
                    List<String> names = new ArrayList<>();
                    for (QcConfig.Test t : qc.tests().get(tv.name())) {
                        names.add("qartod_" + tv.name() + "_" + t.shortName() + "_flag");
                    }
                    names.add("qartod_" + tv.name() + "_primary_flag");
                    v = v + " " + String.join(" ", names);
                }
                list.add(attribute(a.getKey(), v));
            }
            attributes.put(tv.name(), List.copyOf(list));
            dimensions.add(String.join(" ", tv.dims()));
        }
        for (Map.Entry<String, Object> g : template.globals().entrySet()) {
            String k = g.getKey();
            boolean dated = k.equals("date_created") || k.equals("date_modified");
            globalNames.add(k);
            fixedGlobals.add(dated ? null : attribute(k, meta.global().containsKey(k) ? meta.global().get(k) : g.getValue()));
        }
        for (Map.Entry<String, String> e : meta.global().entrySet()) {
            if (!template.globals().containsKey(e.getKey())) {
                globalNames.add(e.getKey());
                fixedGlobals.add(new Attribute(e.getKey(), e.getValue()));
            }
        }
        globalNames.add("cdm_data_type");
        fixedGlobals.add(new Attribute("cdm_data_type", "Trajectory"));
        globalNames.add("featureType");
        fixedGlobals.add(new Attribute("featureType", "trajectory"));
        for (Map.Entry<String, List<QcConfig.Test>> e : qc.tests().entrySet()) {
            for (QcConfig.Test t : e.getValue()) {
                attributes.put("qartod_" + e.getKey() + "_" + t.shortName() + "_flag", flagAttributes(e.getKey(), t.shortName(), t.json()));
            }
            attributes.put("qartod_" + e.getKey() + "_primary_flag", flagAttributes(e.getKey(), "primary", null));
        }
    }

    private static List<Attribute> flagAttributes(String var, String test, String config) {
        boolean primary = test.equals("primary");
        List<Attribute> a = new ArrayList<>();
        a.add(new Attribute("_FillValue", (byte) 9));
        a.add(new Attribute("long_name", primary ? "QARTOD Primary Flag for " + var : "QARTOD " + test.replace('_', ' ') + " test flag for " + var));
        a.add(new Attribute("standard_name", primary ? "aggregate_quality_flag" : test + "_test_quality_flag"));
        a.add(new Attribute("flag_values", Array.factory(new byte[] {1, 2, 3, 4, 9})));
        a.add(new Attribute("flag_meanings", "GOOD NOT_EVALUATED SUSPECT FAIL MISSING"));
        a.add(new Attribute("valid_min", (byte) 1));
        a.add(new Attribute("valid_max", (byte) 9));
        a.add(new Attribute("ioos_qc_module", "qartod"));
        a.add(new Attribute("ioos_qc_test", primary ? "aggregate" : test + "_test"));
        a.add(new Attribute("ioos_qc_target", var));
        if (config != null) {
            a.add(new Attribute("ioos_qc_config", config));
        }
        a.add(new Attribute("references", "https://ioos.noaa.gov/project/qartod/"));
        return List.copyOf(a);
    }

    /** The DAC's name for a profile's file: {@code glider_yyyymmddTHHMMSSZ_rt.nc} (real time) or {@code _delayed.nc}. */
    public static String fileName(Profile p) {
        return p.vehicle() + "_" + NAME_TIME.format(Instant.ofEpochMilli((long) Math.floor(p.time()[0] * 1000))) + "Z"
                + (p.delayed() ? "_delayed" : "_rt") + ".nc";
    }

    /** Writes the profile into {@code dir}; returns the file. */
    public Path write(Profile p, Path dir) throws IOException {
        return writeUnchecked(p, dir);
    }

    /**
     * Writes the profile into {@code dir}, checked before it takes its name: a file the checker
     * fails becomes {@code NAME.failed} (the report says why), so no failing file ever has a name an
     * upload would pick up. Returns the file and its report (null without a checker).
     */
    public Path write(Profile p, Path dir, ProfileChecker checker, ProfileChecker.Report[] report) throws IOException {
        return writeThenName(p, dir, (tmp, target) -> {
            ProfileChecker.Report r = checker.check(tmp);
            report[0] = new ProfileChecker.Report(target, r.failures(), r.warnings());
            Path to = r.passed() ? target : dir.resolve(target.getFileName() + ".failed");
            Files.move(tmp, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            return to;
        });
    }

    private Path writeUnchecked(Profile p, Path dir) throws IOException {
        return writeThenName(p, dir, (tmp, target) -> {
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            return target;
        });
    }

    /** Gives a written temporary file its name (or another); returns where it went. */
    private interface Naming {
        Path name(Path tmp, Path target) throws IOException;
    }

    /** Writes into NAME.tmp, then lets {@code naming} move it; a failure leaves no .tmp behind. */
    private Path writeThenName(Profile p, Path dir, Naming naming) throws IOException {
        Path target = dir.resolve(fileName(p));
        Path tmp = dir.resolve(target.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        boolean done = false;
        try {
            writeTo(p, tmp);
            Path to = naming.name(tmp, target);
            done = true;
            return to;
        } finally {
            if (!done) {
                Files.deleteIfExists(tmp);
            }
        }
    }

    /** The flags of every configured test, and the primary flag, per variable. */
    public Map<String, Map<String, byte[]>> flags(Profile p) {
        Map<String, Map<String, byte[]>> out = new LinkedHashMap<>();
        for (Map.Entry<String, List<QcConfig.Test>> e : qc.tests().entrySet()) {
            Map<String, byte[]> f = new LinkedHashMap<>();
            Map<QcConfig.Test, byte[]> run = QcConfig.run(e.getValue(), p.values(e.getKey()), p.time());
            run.forEach((t, flags) -> f.put(t.shortName(), flags));
            f.put("primary", Qartod.aggregate(new ArrayList<>(run.values()), p.size()));
            out.put(e.getKey(), f);
        }
        return out;
    }

    void writeTo(Profile p, Path file) throws IOException {
        Map<String, Map<String, byte[]>> flags = flags(p);
        NetcdfFileWriter w = NetcdfFileWriter.createNew(NetcdfFileWriter.Version.netcdf3, file.toString());
        try {
            Dimension time = w.addUnlimitedDimension("time");
            w.addDimension(null, "traj_strlen", 20);
            Map<String, Variable> vars = new LinkedHashMap<>();
            List<CdlTemplate.Var> tvs = template.variables();
            for (int i = 0; i < tvs.size(); i++) {
                CdlTemplate.Var tv = tvs.get(i);
                Variable v = w.addVariable(null, tv.name(), type(tv.type()), dimensions.get(i));
                for (Attribute a : attributes.get(tv.name())) {
                    w.addVariableAttribute(v, a);
                }
                vars.put(tv.name(), v);
            }
            for (Map.Entry<String, Map<String, byte[]>> e : flags.entrySet()) {
                for (String test : e.getValue().keySet()) {
                    String name = "qartod_" + e.getKey() + "_" + test + "_flag";
                    Variable v = w.addVariable(null, name, DataType.BYTE, time.getShortName());
                    for (Attribute a : attributes.get(name)) {
                        w.addVariableAttribute(v, a);
                    }
                    vars.put(name, v);
                }
            }
            globals(w, p);
            w.create();
            write(w, vars, p, flags);
        } catch (InvalidRangeException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        } finally {
            w.close();
        }
    }

    private Object value(CdlTemplate.Var tv, String attr, Object templateValue) {
        if (tv.name().equals("platform") && meta.platform().containsKey(attr)) {
            return meta.platform().get(attr);
        }
        if (tv.name().equals("instrument_ctd") && meta.instrumentCtd().containsKey(attr)) {
            return meta.instrumentCtd().get(attr);
        }
        if ((attr.equals("valid_min") || attr.equals("valid_max")) && tv.type().equals("double") && templateValue instanceof int[] i) {
            return new double[] {i[0]};
        }
        return templateValue;
    }

    private void globals(NetcdfFileWriter w, Profile p) {
        String now = ISO.format(Instant.now());
        for (int i = 0; i < fixedGlobals.size(); i++) {
            Attribute a = fixedGlobals.get(i);
            w.addGroupAttribute(null, a != null ? a : new Attribute(globalNames.get(i), now));
        }
        w.addGroupAttribute(null, new Attribute("source_file", p.segment()));
        w.addGroupAttribute(null, new Attribute("time_coverage_start", ISO.format(Instant.ofEpochSecond((long) Math.floor(p.time()[0])))));
        w.addGroupAttribute(null, new Attribute("time_coverage_end", ISO.format(Instant.ofEpochSecond((long) Math.floor(p.time()[p.size() - 1])))));
    }

    private void write(NetcdfFileWriter w, Map<String, Variable> vars, Profile p, Map<String, Map<String, byte[]>> flags)
            throws IOException, InvalidRangeException {
        int n = p.size();
        int[] origin = {0};
        byte[] qcFlags = new byte[n]; // one buffer for every _qc variable: each write copies it to the file before the next fills it
        for (String s : SERIES) {
            double[] values = p.values(s);
            w.write(vars.get(s), origin, Array.factory(filled(values)));
            Map<String, byte[]> f = flags.get(s);
            if (f == null) {
                for (int i = 0; i < n; i++) {
                    qcFlags[i] = Double.isNaN(values[i]) ? (byte) 9 : 0;
                }
            } else {
                byte[] primary = f.get("primary");
                for (int i = 0; i < n; i++) {
                    qcFlags[i] = dacFlag(primary[i]);
                }
            }
            w.write(vars.get(s + "_qc"), origin, Array.factory(qcFlags));
        }
        for (Map.Entry<String, Map<String, byte[]>> e : flags.entrySet()) {
            for (Map.Entry<String, byte[]> t : e.getValue().entrySet()) {
                w.write(vars.get("qartod_" + e.getKey() + "_" + t.getKey() + "_flag"), origin, Array.factory(t.getValue()));
            }
        }
        ArrayChar.D1 traj = new ArrayChar.D1(20);
        String name = meta.trajectory() != null ? meta.trajectory() : p.vehicle();
        traj.setString(name.length() > 20 ? name.substring(0, 20) : name);
        w.write(vars.get("trajectory"), traj);
        w.write(vars.get("profile_id"), Array.factory(DataType.INT, new int[0], new int[] {p.id()}));
        for (String s : List.of("profile_time", "profile_lat", "profile_lon", "time_uv", "lat_uv", "lon_uv", "u", "v")) {
            double x = p.scalar(s);
            w.write(vars.get(s), Array.factory(DataType.DOUBLE, new int[0], new double[] {Double.isFinite(x) ? x : FILL}));
            w.write(vars.get(s + "_qc"), Array.factory(DataType.BYTE, new int[0], new byte[] {Double.isFinite(x) ? (byte) 0 : (byte) 9}));
        }
        w.write(vars.get("platform"), Array.factory(DataType.INT, new int[0], new int[] {-999}));
        w.write(vars.get("instrument_ctd"), Array.factory(DataType.INT, new int[0], new int[] {-999}));
    }

    /** QARTOD's flag in the template's {@code _qc} meanings: "not evaluated" is "no QC performed" (0); the others keep their number. */
    static byte dacFlag(byte qartod) {
        return qartod == Qartod.UNKNOWN ? 0 : qartod;
    }

    /** The values with the template's fill value for a missing one: the array itself when none is missing (NetCDF-Java only reads it). */
    private static double[] filled(double[] v) {
        int i = 0;
        while (i < v.length && Double.isFinite(v[i])) {
            i++;
        }
        if (i == v.length) {
            return v;
        }
        double[] out = v.clone();
        for (; i < v.length; i++) {
            out[i] = Double.isFinite(v[i]) ? v[i] : FILL;
        }
        return out;
    }

    private static DataType type(String cdl) {
        return switch (cdl) {
            case "char" -> DataType.CHAR;
            case "byte" -> DataType.BYTE;
            case "short" -> DataType.SHORT;
            case "int" -> DataType.INT;
            case "float" -> DataType.FLOAT;
            default -> DataType.DOUBLE;
        };
    }

    private static Attribute attribute(String name, Object v) {
        if (v instanceof String s) {
            return new Attribute(name, s);
        }
        if (v instanceof byte[] b) {
            return b.length == 1 ? new Attribute(name, b[0]) : new Attribute(name, Array.factory(b));
        }
        if (v instanceof int[] i) {
            return i.length == 1 ? new Attribute(name, i[0]) : new Attribute(name, Array.factory(i));
        }
        double[] d = (double[]) v;
        return d.length == 1 ? new Attribute(name, d[0]) : new Attribute(name, Array.factory(d));
    }
}
