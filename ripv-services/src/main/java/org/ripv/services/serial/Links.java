package org.ripv.services.serial;

import java.io.IOException;

/** Opens the right kind of {@link Link} for a device name. */
public final class Links {
    private Links() {
    }

    /** A {@link TcpLink} for {@code tcp://host:port}, else a {@link SerialLink}. */
    public static Link open(LinkSettings settings) throws IOException {
        if (VehicleLink.isListen(settings.device())) {
            throw new IOException(settings.device() + " is not opened: the vehicle calls in");
        }
        if (settings.isTcp()) {
            return TcpLink.connect(settings.device(), 5_000);
        }
        return SerialLink.open(settings);
    }
}
