package org.ripv.services.serial;

import java.time.Duration;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import org.ripv.commands.SingleLineCommand;
import org.ripv.launch.OptionChecks;
import org.ripv.services.serial.ymodem.YmodemConfig;

/**
 * How one link is opened and talked to.
 *
 * @param device          a device path ({@code /dev/ttyUSB0}, {@code /tmp/ttyV0}, {@code COM3}) or
 *                        {@code tcp://host:port}
 * @param baud            bits per second (serial only)
 * @param dataBits        5–8
 * @param parity          none, odd, even, mark or space
 * @param stopBits        1, 1.5 or 2
 * @param lineEnding      what ends a command line written to the vehicle
 * @param prompt          the vehicle's prompt; a reply ends where the text ends with it
 * @param idleTimeout     a reply also ends when the vehicle has been silent this long
 * @param commandTimeout  the longest any plain command may take
 * @param carrier         whether DCD must be high to talk
 * @param sendCommand     the vehicle's command that sends files by YMODEM ({@code ys})
 * @param receiveCommand  the vehicle's command that receives files by YMODEM ({@code yr})
 * @param reconnectEvery  how often a down link is retried and an idle one checked
 * @param ymodem          YMODEM timeouts and retries
 * @param maxCommand      the longest command written to this link ({@code maxcommand=}, default
 *                        {@link SingleLineCommand#DEFAULT_MAX}); longer ones are refused
 * @param interrupt       what {@code ?cancel} writes to stop a running plain command
 *                        ({@code interrupt=}, default Ctrl-C, {@link Interrupt}); empty: the link
 *                        has none and plain commands cannot be cancelled
 */
public record LinkSettings(String device, int baud, int dataBits, Parity parity, StopBits stopBits,
                           String lineEnding, Pattern prompt, Duration idleTimeout, Duration commandTimeout,
                           CarrierMode carrier, String sendCommand, String receiveCommand,
                           Duration reconnectEvery, YmodemConfig ymodem, int maxCommand, String interrupt) {

    /** PicoDOS's prompt. */
    public static final String DEFAULT_PROMPT = "C:\\>";

    /** Parity as jSerialComm numbers it. */
    public enum Parity { NONE, ODD, EVEN, MARK, SPACE;
        public static Parity parse(String s) {
            try {
                return valueOf(s.trim().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("parity '" + s + "' is not one of none, odd, even, mark, space");
            }
        }
    }

    /** Stop bits as jSerialComm numbers them (1, 1.5, 2). */
    public enum StopBits { ONE("1"), ONE_POINT_FIVE("1.5"), TWO("2");
        private final String text;

        StopBits(String text) {
            this.text = text;
        }

        public static StopBits parse(String s) {
            for (StopBits b : values()) {
                if (b.text.equals(s.trim())) {
                    return b;
                }
            }
            throw new IllegalArgumentException("stop bits '" + s + "' is not one of 1, 1.5, 2");
        }

        @Override
        public String toString() {
            return text;
        }
    }

    public LinkSettings {
        Objects.requireNonNull(device, "device");
        if (device.isBlank()) {
            throw new IllegalArgumentException("empty device name");
        }
        OptionChecks.within("baud", baud, 50, 4_000_000);
        OptionChecks.within("data bits", dataBits, 5, 8);
        Objects.requireNonNull(parity, "parity");
        Objects.requireNonNull(stopBits, "stopBits");
        Objects.requireNonNull(lineEnding, "lineEnding");
        Objects.requireNonNull(prompt, "prompt");
        requirePositive(idleTimeout, "idle timeout");
        requirePositive(commandTimeout, "command timeout");
        requirePositive(reconnectEvery, "reconnect interval");
        Objects.requireNonNull(carrier, "carrier");
        Objects.requireNonNull(sendCommand, "sendCommand");
        Objects.requireNonNull(receiveCommand, "receiveCommand");
        Objects.requireNonNull(ymodem, "ymodem");
        OptionChecks.within("maxcommand", maxCommand, 1, SingleLineCommand.SERVER_MAX); // the server's cap
        Objects.requireNonNull(interrupt, "interrupt");
    }

    /** Settings with the default interrupt, Ctrl-C. */
    public LinkSettings(String device, int baud, int dataBits, Parity parity, StopBits stopBits,
                        String lineEnding, Pattern prompt, Duration idleTimeout, Duration commandTimeout,
                        CarrierMode carrier, String sendCommand, String receiveCommand,
                        Duration reconnectEvery, YmodemConfig ymodem, int maxCommand) {
        this(device, baud, dataBits, parity, stopBits, lineEnding, prompt, idleTimeout, commandTimeout, carrier,
                sendCommand, receiveCommand, reconnectEvery, ymodem, maxCommand, Interrupt.CTRL_C);
    }

    /** Settings with the default command length limit. */
    public LinkSettings(String device, int baud, int dataBits, Parity parity, StopBits stopBits,
                        String lineEnding, Pattern prompt, Duration idleTimeout, Duration commandTimeout,
                        CarrierMode carrier, String sendCommand, String receiveCommand,
                        Duration reconnectEvery, YmodemConfig ymodem) {
        this(device, baud, dataBits, parity, stopBits, lineEnding, prompt, idleTimeout, commandTimeout, carrier,
                sendCommand, receiveCommand, reconnectEvery, ymodem, SingleLineCommand.DEFAULT_MAX);
    }

    private static void requirePositive(Duration d, String what) {
        if (d == null || d.isNegative() || d.isZero()) {
            throw new IllegalArgumentException(what + " must be positive, got " + d);
        }
    }

    /** The defaults for {@code device}: 115200 8N1, CR LF, prompt {@code C:\>}, 2 s idle, carrier ignored. */
    public static LinkSettings defaults(String device) {
        return new LinkSettings(device, 115200, 8, Parity.NONE, StopBits.ONE, "\r\n",
                Pattern.compile(Pattern.quote(DEFAULT_PROMPT)), Duration.ofSeconds(2), Duration.ofSeconds(60),
                CarrierMode.IGNORE, "ys", "yr", Duration.ofSeconds(2), YmodemConfig.lrzsz());
    }

    public boolean isTcp() {
        return device.startsWith("tcp://");
    }

    public LinkSettings withDevice(String newDevice) {
        return with(d -> d.device = newDevice);
    }

    public LinkSettings withIdleTimeout(Duration idle) {
        return with(d -> d.idleTimeout = idle);
    }

    public LinkSettings withReconnectEvery(Duration every) {
        return with(d -> d.reconnectEvery = every);
    }

    /** With another prompt, e.g. GliderDOS's and PicoDOS's for a Slocum (prompt-regex= on the command line). */
    public LinkSettings withPrompt(Pattern newPrompt) {
        return with(d -> d.prompt = newPrompt);
    }

    public LinkSettings withYmodem(YmodemConfig config) {
        return with(d -> d.ymodem = config);
    }

    public LinkSettings withVehicleCommands(String send, String receive) {
        return with(d -> {
            d.sendCommand = send;
            d.receiveCommand = receive;
        });
    }

    public LinkSettings withCarrier(CarrierMode mode) {
        return with(d -> d.carrier = mode);
    }

    public LinkSettings withMaxCommand(int max) {
        return with(d -> d.maxCommand = max);
    }

    public LinkSettings withInterrupt(String keys) {
        return with(d -> d.interrupt = keys);
    }

    /** A copy with what {@code change} sets changed: the one place that lists every component. */
    private LinkSettings with(Consumer<Draft> change) {
        Draft d = new Draft(this);
        change.accept(d);
        return new LinkSettings(d.device, baud, dataBits, parity, stopBits, lineEnding, d.prompt, d.idleTimeout,
                commandTimeout, d.carrier, d.sendCommand, d.receiveCommand, d.reconnectEvery, d.ymodem, d.maxCommand,
                d.interrupt);
    }

    /** The components a wither may change, copied from settings. */
    private static final class Draft {
        String device;
        Pattern prompt;
        Duration idleTimeout;
        CarrierMode carrier;
        String sendCommand;
        String receiveCommand;
        Duration reconnectEvery;
        YmodemConfig ymodem;
        int maxCommand;
        String interrupt;

        Draft(LinkSettings s) {
            device = s.device;
            prompt = s.prompt;
            idleTimeout = s.idleTimeout;
            carrier = s.carrier;
            sendCommand = s.sendCommand;
            receiveCommand = s.receiveCommand;
            reconnectEvery = s.reconnectEvery;
            ymodem = s.ymodem;
            maxCommand = s.maxCommand;
            interrupt = s.interrupt;
        }
    }

    /** {@code 115200 8N1} */
    public String frameDescription() {
        return baud + " " + dataBits + parity.name().charAt(0) + stopBits;
    }
}
