package org.ripv.services.serial;

import com.fazecast.jSerialComm.SerialPort;
import com.fazecast.jSerialComm.SerialPortInvalidPortException;
import java.io.EOFException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A serial device through jSerialComm: an enumerated port, or any device path such as a
 * pseudo-terminal (jSerialComm does not enumerate ptys; symlinks are resolved first).
 *
 * <p>Two jSerialComm habits are handled here: a peer that has gone shows up as
 * {@code readBytes} = -1 while {@code isOpen()} stays true (turned into an
 * {@link EOFException}), and {@code closePort()} discards unsent bytes (so close drains first).
 */
public final class SerialLink implements Link {
    private static final Logger log = LoggerFactory.getLogger(SerialLink.class);
    private final SerialPort port;
    private final String description;
    private final int baud;
    private int readTimeout = -1;

    private SerialLink(SerialPort port, String description, int baud) {
        this.port = port;
        this.description = description;
        this.baud = baud;
    }

    /** Opens {@code settings.device()} with its baud rate and framing. */
    public static SerialLink open(LinkSettings settings) throws IOException {
        String device = settings.device();
        String path = device;
        Path p = Path.of(device);
        if (device.contains("/") && !Files.exists(p)) {
            throw new IOException("no serial device at '" + device + "' (it does not exist)");
        }
        if (Files.isSymbolicLink(p)) {
            path = p.toRealPath().toString();
        }
        SerialPort port;
        try {
            port = SerialPort.getCommPort(path);
        } catch (SerialPortInvalidPortException e) {
            throw new IOException("no serial device '" + device + "': " + e.getMessage(), e);
        }
        port.setComPortParameters(settings.baud(), settings.dataBits(), switch (settings.stopBits()) {
            case ONE -> SerialPort.ONE_STOP_BIT;
            case ONE_POINT_FIVE -> SerialPort.ONE_POINT_FIVE_STOP_BITS;
            case TWO -> SerialPort.TWO_STOP_BITS;
        }, switch (settings.parity()) {
            case NONE -> SerialPort.NO_PARITY;
            case ODD -> SerialPort.ODD_PARITY;
            case EVEN -> SerialPort.EVEN_PARITY;
            case MARK -> SerialPort.MARK_PARITY;
            case SPACE -> SerialPort.SPACE_PARITY;
        });
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        if (!port.openPort()) {
            throw new IOException("cannot open serial device '" + device + "'"
                    + (path.equals(device) ? "" : " (" + path + ")") + ": error " + port.getLastErrorCode()
                    + "; check that it exists and that this user may open it");
        }
        String description = device + (path.equals(device) ? "" : " -> " + path) + " at " + settings.frameDescription();
        log.info("opened {}", description);
        return new SerialLink(port, description, settings.baud());
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        int t = (int) Math.max(1, Math.min(Integer.MAX_VALUE, timeoutMillis));
        if (t != readTimeout) {
            port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING, t, 0);
            readTimeout = t;
        }
        int n = port.readBytes(buffer, len, offset);
        if (n < 0) {
            throw new EOFException(description + ": the device or its peer has gone");
        }
        return n;
    }

    @Override
    public void write(byte[] buffer, int offset, int len) throws IOException {
        int done = 0;
        while (done < len) {
            int n = port.writeBytes(buffer, len - done, offset + done);
            if (n < 0) {
                throw new EOFException(description + ": write failed, the device or its peer has gone");
            }
            done += n;
        }
    }

    @Override
    public String describe() {
        return description;
    }

    @Override
    public boolean hasCarrierLine() {
        return true;
    }

    @Override
    public boolean carrier() {
        return port.getDCD();
    }

    @Override
    public void close() {
        // closePort() throws away what the driver has not sent yet: wait the time the line needs
        int waiting = Math.max(0, port.bytesAwaitingWrite());
        if (waiting > 0) {
            long millis = waiting * 10_000L / baud + 50;
            try {
                TimeUnit.MILLISECONDS.sleep(Math.min(millis, 5_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        port.closePort();
        log.info("closed {}", description);
    }
}
