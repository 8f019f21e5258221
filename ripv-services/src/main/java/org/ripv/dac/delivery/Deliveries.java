package org.ripv.dac.delivery;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ripv.dac.DacException;
import org.ripv.services.ingest.SensorListCache;

/**
 * The DatabaseServer's deployments ({@code --dac FILE}, one per glider) and its one hook: the
 * ingest hands each Slocum file it stored to {@link #arrived}, which passes it to the deployment
 * of that glider, and the MailBox's {@code dac:status [--json]} is {@link #status}.
 */
public final class Deliveries implements AutoCloseable {
    /** No deployment: arrivals are ignored, {@code dac:status} says none is configured. */
    public static final Deliveries NONE = new Deliveries(List.of());
    /** The MailBox command that shows the deliveries (the server's {@code ?dac MAILBOX} sends it). */
    public static final String COMMAND = "dac:status";

    private final List<Delivery> deliveries;

    private Deliveries(List<Delivery> deliveries) {
        this.deliveries = deliveries;
    }

    /** Reads and starts every deployment; the first one that is refused stops them all, with its reasons. */
    public static Deliveries start(List<Path> files) throws DacException, IOException {
        List<Delivery> started = new ArrayList<>();
        try {
            for (Path f : files) {
                Deployment d = Deployment.read(f);
                for (Delivery other : started) {
                    if (other.deployment().glider().equalsIgnoreCase(d.glider())) {
                        throw new DacException(f + ": the glider " + d.glider() + " has a deployment already ("
                                + other.deployment().file() + ")");
                    }
                }
                started.add(Delivery.start(d));
            }
        } catch (DacException | IOException | RuntimeException e) {
            started.forEach(Delivery::close);
            throw e;
        }
        return new Deliveries(List.copyOf(started));
    }

    public List<Delivery> all() {
        return deliveries;
    }

    /** A Slocum file the ingest stored: to the deployment of its glider, if any. Returns at once. */
    public void arrived(String name, byte[] data, SensorListCache cache) {
        for (Delivery d : deliveries) {
            if (d.takes(name)) {
                d.arrived(name, data, cache);
            }
        }
    }

    /** True when a MailBox command is {@code dac:status ...}. */
    public static boolean matches(String command) {
        String c = command == null ? "" : command.strip().toLowerCase(Locale.ROOT);
        return c.equals(COMMAND) || c.startsWith(COMMAND + " ");
    }

    /**
     * {@code dac:status [GLIDER] [--json]}: every deployment's state (or one glider's), as text or
     * as a JSON array of objects.
     *
     * @throws IllegalArgumentException for an unknown option or glider
     */
    public String status(List<String> args) {
        boolean json = false;
        String glider = null;
        for (String a : args) {
            if (a.equalsIgnoreCase("--json")) {
                json = true;
            } else if (a.startsWith("-") || glider != null) {
                throw new IllegalArgumentException("usage: " + COMMAND + " [GLIDER] [--json]");
            } else {
                glider = a;
            }
        }
        List<Delivery> shown = new ArrayList<>();
        for (Delivery d : deliveries) {
            if (glider == null || d.deployment().glider().equalsIgnoreCase(glider)) {
                shown.add(d);
            }
        }
        if (glider != null && shown.isEmpty()) {
            throw new IllegalArgumentException("no DAC deployment of " + glider + " here; " + (deliveries.isEmpty()
                    ? "none is configured (--dac FILE)" : "there are " + deliveries.stream().map(d -> d.deployment().glider()).toList()));
        }
        if (json) {
            List<Map<String, Object>> all = shown.stream().map(Delivery::json).toList();
            try {
                return new ObjectMapper().writeValueAsString(all);
            } catch (JsonProcessingException e) {
                throw new IllegalStateException("the delivery state could not be written as JSON", e);
            }
        }
        if (shown.isEmpty()) {
            return "no DAC deployment is configured on this DatabaseServer (start it with --dac FILE, docs/dac.md)";
        }
        return String.join("\n\n", shown.stream().map(Delivery::text).toList());
    }

    @Override
    public void close() {
        deliveries.forEach(Delivery::close);
    }
}
