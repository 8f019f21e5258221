package org.ripv.services.serial;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import picocli.CommandLine.IModelTransformer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The settings a link may have, each named once: its key after the device
 * ({@code --link /dev/ttyUSB0,baud=9600}), the option that gives every link its default
 * ({@code --baud 9600}; none for what only a link may say, such as its name), that default and its
 * help. {@link SerialPortServerCommand} declares those options from this table (as a picocli model
 * transformer) and reads a link's values through {@link #values}, so the command line and a link's
 * own settings cannot drift apart: a new setting is one row here.
 */
final class LinkOptions implements IModelTransformer {

    /** One setting; {@code option} is null where only a link may set it. */
    record Setting(String key, String option, String defaultValue, String label, String help) {}

    static final List<Setting> TABLE = List.of(
            new Setting("baud", "--baud", "115200", "BAUD", "Baud rate (default ${DEFAULT-VALUE})."),
            new Setting("data-bits", "--data-bits", "8", "BITS", "Data bits 5-8 (default ${DEFAULT-VALUE})."),
            new Setting("parity", "--parity", "none", "PARITY", "none, odd, even, mark or space (default ${DEFAULT-VALUE})."),
            new Setting("stop-bits", "--stop-bits", "1", "BITS", "1, 1.5 or 2 (default ${DEFAULT-VALUE})."),
            new Setting("carrier", "--carrier", "ignore", "MODE", "require: send nothing while DCD is low and report the"
                    + " MailBox not available; ignore (ptys, TCP). Default ${DEFAULT-VALUE}."),
            new Setting("line-ending", "--line-ending", "crlf", "ENDING",
                    "cr, lf or crlf after each command (default ${DEFAULT-VALUE})."),
            new Setting("prompt", "--prompt", LinkSettings.DEFAULT_PROMPT, "TEXT",
                    "The vehicle's prompt, literally (default ${DEFAULT-VALUE})."),
            new Setting("prompt-regex", "--prompt-regex", null, "REGEX",
                    "The vehicle's prompt as a Java regular expression (instead of --prompt)."),
            new Setting("idle-timeout", "--idle-timeout", "2000", "MILLIS",
                    "A reply ends after this much silence if no prompt came (default ${DEFAULT-VALUE} ms)."),
            new Setting("command-timeout", "--command-timeout", "60", "SECONDS",
                    "The longest a plain command may run (default ${DEFAULT-VALUE} s)."),
            new Setting("send-command", "--send-command", "ys", "COMMAND",
                    "The vehicle's YMODEM send command, given the names (default ${DEFAULT-VALUE})."),
            new Setting("receive-command", "--receive-command", "yr", "COMMAND",
                    "The vehicle's YMODEM receive command (default ${DEFAULT-VALUE})."),
            new Setting("maxcommand", "--max-command", "1024", "CHARS", "The longest command written to a link"
                    + " (per link: maxcommand=N); longer ones are refused (default ${DEFAULT-VALUE}, at most 16384)."),
            new Setting("interrupt", "--interrupt", "^C", "KEYS", "What ?cancel writes to stop a running vehicle command:"
                    + " ^C, \\x03, text, or none (per link: interrupt=; default ${DEFAULT-VALUE})."),
            new Setting("name", null, null, null, null),
            new Setting("surface", "--surface", CallSettings.DEFAULT_SURFACE, "REGEX",
                    "On links with neither carrier nor caller: output that marks a call's start (default ${DEFAULT-VALUE})."),
            new Setting("quiet", "--quiet", "600", "SECONDS",
                    "On those links: silence this long ends the call, DIVED (default ${DEFAULT-VALUE} s)."),
            new Setting("alert", "--alert", CallSettings.DEFAULT_ALERT, "REGEX",
                    "Output lines that raise an ALERT event (default ${DEFAULT-VALUE})."),
            new Setting("line-length", "--line-length", "1024", "CHARS",
                    "Console lines are cut at this length (default ${DEFAULT-VALUE})."),
            new Setting("rate", "--rate", "200", "LINES", "Console lines per second per link; the excess is marked"
                    + " 'N lines skipped' (default ${DEFAULT-VALUE})."),
            new Setting("callers", "--callers", null, "CIDR[,CIDR...]", "On listen:// links: take calls only from these"
                    + " addresses, e.g. the RUDICS gateway's (per link: callers=...; default: anyone who can reach the port)."),
            new Setting("overdue", null, null, null, null),
            new Setting("keys", "--keys", ControlKey.DEFAULT_KEYS, "KEY[,KEY...]", "The control keys ?key may press on a"
                    + " vehicle, ctrl-a … ctrl-z, or none (per link: keys=; default ${DEFAULT-VALUE})."),
            new Setting("zmodem-send", "--zmodem-send", "zs", "COMMAND", "The vehicle's ZMODEM send command, given the"
                    + " names (per link: zmodem-send=; default ${DEFAULT-VALUE})."),
            new Setting("zmodem-receive", "--zmodem-receive", "zr", "COMMAND",
                    "The vehicle's ZMODEM receive command (per link: zmodem-receive=; default ${DEFAULT-VALUE})."),
            new Setting("to-vehicle", null, "off", null, null));

    /** Declares an option for every setting that has one. */
    @Override
    public CommandSpec transform(CommandSpec spec) {
        for (Setting s : TABLE) {
            if (s.option() != null) {
                spec.addOption(OptionSpec.builder(s.option()).type(String.class).paramLabel(s.label())
                        .defaultValue(s.defaultValue()).description(s.help()).build());
            }
        }
        return spec;
    }

    /** A {@code --link} argument: its device and the settings written after it. */
    record Link(String device, Map<String, String> own) {
        /** Splits {@code DEVICE,key=value,...}; refuses a key that is no setting. */
        static Link parse(String spec) {
            String[] parts = spec.split(",(?=[a-z-]+=)");
            Map<String, String> own = new LinkedHashMap<>();
            for (int i = 1; i < parts.length; i++) {
                String key = parts[i].substring(0, parts[i].indexOf('='));
                if (TABLE.stream().noneMatch(s -> s.key().equals(key))) {
                    throw new IllegalArgumentException("--link '" + spec + "': unknown setting '" + key
                            + "'; a link may set " + new TreeSet<>(TABLE.stream().map(Setting::key).toList()));
                }
                own.put(key, parts[i].substring(key.length() + 1));
            }
            return new Link(parts[0], own);
        }
    }

    /**
     * Every setting of a link by key (absent: none): the command line's value or default, with the
     * link's own over it. A link's own {@code prompt=} replaces the command line's {@code --prompt-regex} too.
     */
    static Map<String, String> values(CommandSpec spec, Link link) {
        Map<String, String> values = new HashMap<>();
        for (Setting s : TABLE) {
            String v = s.option() != null ? spec.findOption(s.option()).getValue() : s.defaultValue();
            if (v != null) {
                values.put(s.key(), v);
            }
        }
        if (link.own().containsKey("prompt")) {
            values.remove("prompt-regex");
        }
        values.putAll(link.own());
        return values;
    }
}
