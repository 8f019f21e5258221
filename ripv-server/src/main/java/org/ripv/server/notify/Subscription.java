package org.ripv.server.notify;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.regex.Pattern;
import org.ripv.messages.NotifyList;
import org.ripv.messages.VehicleEvent;
import org.ripv.json.Json;

/** One user's subscription: a channel, a target, the events and a MailBox glob; and how it last went. */
final class Subscription {
    enum Channel { WEBHOOK, EMAIL }

    final String id;
    final String user;
    final Channel channel;
    final String target;
    final Set<VehicleEvent> events;
    final boolean allEvents;
    final String glob;
    private final Pattern pattern;
    private volatile String lastResult = "never used";
    /** The end of this subscription's chain of deliveries (guarded by the subscription). */
    CompletableFuture<Void> tail = CompletableFuture.completedFuture(null);

    Subscription(String id, String user, Channel channel, String target, Set<VehicleEvent> events, boolean allEvents,
                 String glob) {
        this.id = id;
        this.user = user;
        this.channel = channel;
        this.target = target;
        this.events = events.isEmpty() ? EnumSet.noneOf(VehicleEvent.class) : EnumSet.copyOf(events);
        this.allEvents = allEvents;
        this.glob = glob;
        this.pattern = globPattern(glob);
    }

    boolean wants(VehicleEvent e, String mailbox) {
        return (allEvents || events.contains(e)) && pattern.matcher(mailbox).matches();
    }

    String lastResult() {
        return lastResult;
    }

    void lastResult(String r) {
        lastResult = r;
    }

    String eventsText() {
        return allEvents ? "all" : String.join(",", events.stream().map(Enum::name).toList());
    }

    NotifyList.Subscription view() {
        return new NotifyList.Subscription(id, user, channel.name().toLowerCase(Locale.ROOT), target, eventsText(), glob,
                lastResult);
    }

    String toJson() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", id);
        m.put("user", user);
        m.put("channel", channel.name());
        m.put("target", target);
        m.put("events", eventsText());
        m.put("mailboxes", glob);
        m.put("lastResult", lastResult);
        return Json.write(m);
    }

    static Subscription fromJson(String line) {
        Map<String, Object> m = Json.parse(line);
        String events = str(m, "events");
        Subscription s = new Subscription(str(m, "id"), str(m, "user"), Channel.valueOf(str(m, "channel")), str(m, "target"),
                parseEvents(events), events.equalsIgnoreCase("all"), str(m, "mailboxes"));
        if (m.get("lastResult") instanceof String r) {
            s.lastResult(r);
        }
        return s;
    }

    private static String str(Map<String, Object> m, String k) {
        if (!(m.get(k) instanceof String s)) {
            throw new IllegalArgumentException("no " + k);
        }
        return s;
    }

    /** A comma list of event names (any case), or {@code all} (an empty set). */
    static Set<VehicleEvent> parseEvents(String list) {
        if (list.equalsIgnoreCase("all")) {
            return EnumSet.noneOf(VehicleEvent.class);
        }
        Set<VehicleEvent> out = EnumSet.noneOf(VehicleEvent.class);
        for (String name : list.split(",")) {
            String n = name.trim().toUpperCase(Locale.ROOT);
            try {
                out.add(VehicleEvent.valueOf(n));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("unknown event '" + name.trim() + "'; events are "
                        + String.join(",", Arrays.stream(VehicleEvent.values()).map(Enum::name).toList()) + " or all");
            }
        }
        if (out.isEmpty()) {
            throw new IllegalArgumentException("name at least one event, or all");
        }
        return out;
    }

    /** {@code *} any run, everything else literal, case-insensitive. */
    static Pattern globPattern(String g) {
        StringBuilder re = new StringBuilder();
        for (char c : g.toCharArray()) {
            re.append(c == '*' ? ".*" : Pattern.quote(String.valueOf(c)));
        }
        return Pattern.compile(re.toString(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE | Pattern.DOTALL);
    }
}
