package org.ripv.services.serial;

import java.io.Closeable;
import org.ripv.services.serial.ymodem.ByteLink;

/**
 * An open connection to a vehicle: a serial device (a real port, a USB adapter, a
 * pseudo-terminal) or a raw TCP endpoint. Reads time out instead of blocking forever, and a
 * peer that has gone shows up as an {@link java.io.EOFException} from {@link #read}.
 */
public interface Link extends ByteLink, Closeable {

    /** What this link is connected to, for messages: {@code /dev/ttyUSB0 at 115200 8N1}. */
    String describe();

    /** True when the link has a Data Carrier Detect line at all (TCP has none). */
    boolean hasCarrierLine();

    /** The state of DCD; true on links without the line. */
    boolean carrier();

    /** Sends what is still buffered, then closes. */
    @Override
    void close();
}
