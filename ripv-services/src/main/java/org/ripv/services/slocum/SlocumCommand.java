package org.ripv.services.slocum;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.ripv.services.ingest.MissingSensorListException;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumFormatException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/** {@code ripv slocum decode FILE... [--cache DIR] [--sensors a,b] [--merge]}. Exit codes: 0 done, 1 a file was refused, 2 usage. */
@Command(name = "slocum", mixinStandardHelpOptions = true, subcommands = SlocumCommand.Decode.class,
        description = "Slocum glider binary files (.sbd .tbd .dbd .ebd, compressed .scd .tcd .dcd .ecd) without Teledyne's tools.")
public final class SlocumCommand implements Callable<Integer> {
    @Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }

    @Command(name = "decode", mixinStandardHelpOptions = true,
            description = {"Prints the DBA text dbd2asc prints: the header, sensor names, units, byte sizes, one row a cycle"
                    + " (NaN where a sensor was not updated).",
                    "Example: ripv slocum decode --cache ~/glider/cac unit_363-2019-166-0-157.sbd"})
    static final class Decode implements Callable<Integer> {
        @Parameters(arity = "1..*", paramLabel = "FILE", description = "Binary data files, plain or compressed.")
        List<Path> files;

        @Option(names = {"-c", "--cache"}, paramLabel = "DIR",
                description = "The sensor-list cache folder (CRC.cac files, names in either case), as dbd2asc -c DIR.")
        Path cache;

        @Option(names = "--sensors", split = ",", paramLabel = "NAME",
                description = "Print only these sensors (in the file's order).")
        List<String> sensors;

        @Option(names = "--merge", description = "Two files, a flight (.sbd/.dbd) and a science (.tbd/.ebd) file of one segment:"
                + " one table of both files' sensors, rows in time order, as dba_merge makes it.")
        boolean merge;

        @Spec
        CommandLine.Model.CommandSpec spec;

        @Override
        public Integer call() throws IOException {
            PrintWriter err = spec.commandLine().getErr();
            if (merge && files.size() != 2) {
                err.println("Error: --merge takes two files (a flight and a science file), got " + files.size());
                return 2;
            }
            SensorListCache c = cache == null ? null : new SensorListCache(cache);
            Writer out = spec.commandLine().getOut();
            try {
                if (merge) {
                    try (InputStream a = Files.newInputStream(files.get(0)); InputStream b = Files.newInputStream(files.get(1))) {
                        new Merge(out, sensors).run(a, files.get(0).getFileName().toString(), b,
                                files.get(1).getFileName().toString(), c);
                    }
                } else {
                    for (Path f : files) {
                        try (InputStream in = Files.newInputStream(f)) {
                            String left = new Merge(out, sensors).one(in, f.getFileName().toString(), c);
                            if (!left.isEmpty()) {
                                out.flush();
                                err.println("Note: " + f.getFileName() + ": " + left);
                            }
                        }
                    }
                }
                return 0;
            } catch (NoSuchFileException e) {
                err.println("Error: no such file: " + e.getFile());
                return 1;
            } catch (SlocumFormatException e) {
                err.println("Error: " + e.getMessage() + (cache == null && e instanceof MissingSensorListException
                        ? " (give the folder of the .cac files with --cache DIR)" : ""));
                return 1;
            } catch (IllegalArgumentException e) {
                err.println("Error: " + e.getMessage());
                return 2;
            } finally {
                out.flush();
            }
        }
    }
}
