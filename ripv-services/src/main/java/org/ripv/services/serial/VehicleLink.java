package org.ripv.services.serial;

import java.net.URI;
import java.util.Objects;
import org.ripv.naming.Handles;

/**
 * One link as the SerialPortServer opens it: how to talk to it ({@link LinkSettings}), how to
 * read its calls and console ({@link CallSettings}), and a pilot's keys and ZMODEM commands
 * ({@link PilotSettings}).
 */
public record VehicleLink(LinkSettings settings, CallSettings call, PilotSettings pilot) {

    public VehicleLink {
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(call, "call");
        Objects.requireNonNull(pilot, "pilot");
        if (isListen(settings.device())) {
            listenUri(settings.device()); // validates
        }
    }

    /** A link with the default pilot settings. */
    public VehicleLink(LinkSettings settings, CallSettings call) {
        this(settings, call, PilotSettings.defaults());
    }

    /** A link with the default call settings. */
    public static VehicleLink of(LinkSettings settings) {
        return new VehicleLink(settings, CallSettings.defaults());
    }

    /** The MailBox handle: {@code name=}, else {@code listen-PORT} or what {@link Handles#forLink} gives. */
    public String handle() {
        if (call.name() != null) {
            return call.name();
        }
        if (isListen()) {
            return "listen-" + listenUri(settings.device()).getPort();
        }
        return Handles.forLink(settings.device());
    }

    /** True for {@code listen://[ADDR:]PORT}: the vehicle (or its gateway) calls in. */
    public boolean isListen() {
        return isListen(settings.device());
    }

    static boolean isListen(String device) {
        return device.startsWith("listen://");
    }

    /** {@code listen://PORT} (loopback) or {@code listen://ADDR:PORT} as a URI with host and port. */
    static URI listenUri(String device) {
        String rest = device.substring("listen://".length());
        // no address: this machine only, like the services' other ports; give 0.0.0.0 (or the
        // gateway-facing address) for vehicles and gateways elsewhere
        URI u = URI.create("listen://" + (rest.matches("\\d+") ? "127.0.0.1:" + rest : rest));
        if (u.getPort() < 0 || u.getPort() > 65535 || u.getHost() == null) {
            throw new IllegalArgumentException("'" + device + "' is not listen://[ADDR:]PORT");
        }
        return u;
    }
}
