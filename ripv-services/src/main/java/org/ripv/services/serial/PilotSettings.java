package org.ripv.services.serial;

import java.util.List;
import java.util.Objects;
import org.ripv.services.serial.ymodem.FileNames;

/**
 * A link's settings for a pilot's work at surfacing (kept apart from {@link LinkSettings} and
 * {@link CallSettings}): the control keys that may be pressed and the vehicle's ZMODEM commands.
 *
 * @param keys           the keys {@code ?key} may send ({@code keys=}, default {@link ControlKey#DEFAULT_KEYS})
 * @param zmodemSend     the vehicle's command that sends files by ZMODEM, given their names ({@code zs})
 * @param zmodemReceive  the vehicle's command that receives a file by ZMODEM ({@code zr})
 * @param toVehicle      how the server's {@code to-vehicle/} folder for this link is sent on each
 *                       call ({@code to-vehicle=zmodem|ymodem}); {@link ToVehicleMode#OFF} unless configured
 */
public record PilotSettings(List<ControlKey> keys, String zmodemSend, String zmodemReceive, ToVehicleMode toVehicle) {

    public PilotSettings {
        keys = List.copyOf(keys);
        Objects.requireNonNull(zmodemSend, "zmodemSend");
        Objects.requireNonNull(zmodemReceive, "zmodemReceive");
        if (zmodemSend.isBlank() || zmodemReceive.isBlank()) {
            throw new IllegalArgumentException("the vehicle's ZMODEM commands must not be empty (zmodem-send=, zmodem-receive=)");
        }
        Objects.requireNonNull(toVehicle, "toVehicle");
    }

    /** A link that does not send a to-vehicle folder. */
    public PilotSettings(List<ControlKey> keys, String zmodemSend, String zmodemReceive) {
        this(keys, zmodemSend, zmodemReceive, ToVehicleMode.OFF);
    }

    public static PilotSettings defaults() {
        return new PilotSettings(ControlKey.parseList(ControlKey.DEFAULT_KEYS), "zs", "zr");
    }

    /** Whether the link allows {@code key}. */
    boolean allows(ControlKey key) {
        return keys.contains(key);
    }

    /** The vehicle's ZMODEM send command line for these names. */
    String sendCommand(List<String> names) {
        names.forEach(FileNames::requirePlain);
        return zmodemSend + " " + String.join(" ", names);
    }
}
