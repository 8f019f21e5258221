package org.ripv.services;

import java.io.PrintStream;
import java.util.Arrays;
import org.ripv.dac.DacCommand;
import org.ripv.launch.Version;
import org.ripv.rmi.RmiSupport;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.services.database.DatabaseServerCommand;
import org.ripv.services.datavis.DataVisServerCommand;
import org.ripv.services.serial.SerialPortServerCommand;
import org.ripv.services.simulator.SimulatorCommand;
import org.ripv.launch.Launchers;
import org.ripv.services.slocum.SlocumCommand;
import picocli.CommandLine;

/**
 * {@code java -jar ripv-services.jar SERVICE [OPTIONS]}: runs one of the services (or the glider
 * simulator). The thesis's names and forms work too: {@code SerialPortServer //host},
 * {@code DatabaseServer //host [<driver> <url>]}, {@code DataVisServer //host}.
 */
public final class ServicesMain {
    private ServicesMain() {}

    static final String USAGE = String.join("\n",
            "Usage: java -jar ripv-services.jar SERVICE [OPTIONS]   (SERVICE --help for its options)",
            "  serial    | SerialPortServer   talk to vehicles on serial ports, ptys and TCP links; YMODEM",
            "  database  | DatabaseServer     SQL on embedded Derby, or any JDBC database",
            "  datavis   | DataVisServer      plots from data files through a plotting worker",
            "  simulator                      a simulated glider (PicoDOS-like) on TCP or a pty",
            "  slocum decode FILE...          Slocum binary files as DBA text, as dbd2asc prints them",
            "  dac profiles|check ...         IOOS Glider DAC profile files (NetCDF) with QARTOD flags");

    public static int run(PrintStream err, String... args) {
        if (args.length == 0 || args[0].equals("--help") || args[0].equals("-h")) {
            err.println(USAGE);
            return args.length == 0 ? 2 : 0;
        }
        if (args[0].equals("--version") || args[0].equals("-V")) {
            System.out.println(Version.line());
            return 0;
        }
        String[] rest = Arrays.copyOfRange(args, 1, args.length);
        switch (args[0]) {
            case "serial", "SerialPortServer":
                return execute(new SerialPortServerCommand(), "ripv service serial", ServiceLaunchOptions.thesisForm(rest));
            case "database", "DatabaseServer":
                return execute(new DatabaseServerCommand(), "ripv service database", DatabaseServerCommand.thesisArgs(rest));
            case "datavis", "DataVisServer":
                return execute(new DataVisServerCommand(), "ripv service datavis", ServiceLaunchOptions.thesisForm(rest));
            case "simulator":
                return execute(new SimulatorCommand(), "ripv simulator", rest);
            case "slocum":
                return execute(new SlocumCommand(), "ripv slocum", rest);
            case "dac":
                return execute(new DacCommand(), "ripv dac", rest);
            default:
                err.println("Error: unknown service '" + args[0] + "'");
                err.println(USAGE);
                return 2;
        }
    }

    private static int execute(Object command, String name, String[] args) {
        CommandLine cl = Launchers.commandLine(command, name);
        return cl.execute(args);
    }

    public static void main(String[] args) {
        // Before anything makes an object stream: the JVM takes a filter factory only until then.
        RmiSupport.filterProcess();
        System.exit(run(System.err, args));
    }
}
