package org.ripv.services.serial;

import java.util.Locale;

/**
 * Whether and how a link sends the files waiting in the server's {@code to-vehicle/} folder of its
 * MailBox ({@code to-vehicle=} in its {@code --link}): off unless configured, since a vehicle that
 * is not expecting files must never be sent any.
 */
public enum ToVehicleMode {
    OFF, ZMODEM, YMODEM;

    /** {@code zmodem}, {@code ymodem} or {@code off}. */
    public static ToVehicleMode parse(String word) {
        return switch (word.trim().toLowerCase(Locale.ROOT)) {
            case "zmodem" -> ZMODEM;
            case "ymodem" -> YMODEM;
            case "off", "none" -> OFF;
            default -> throw new IllegalArgumentException("to-vehicle '" + word + "' is not zmodem, ymodem or off");
        };
    }
}
