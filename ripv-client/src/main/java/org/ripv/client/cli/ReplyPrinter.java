package org.ripv.client.cli;

import java.io.PrintStream;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ripv.json.Json;
import org.ripv.messages.FileListing;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Progress;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;
import org.ripv.text.Printable;

/** Prints replies for people (text, aligned tables) or for scripts (one JSON object per line). */
final class ReplyPrinter {
    /** Tables wider than this are cut with an ellipsis per cell. */
    static final int MAX_CELL = 40;

    private final PrintStream out;
    private final PrintStream err;
    private final boolean json;

    ReplyPrinter(PrintStream out, PrintStream err, boolean json) {
        this.out = out;
        this.err = err;
        this.json = json;
    }

    void print(OutgoingServerMessage reply) {
        if (json) {
            out.println(Json.write(toMap(reply)));
            return;
        }
        var f = reply.footer();
        // Text from vehicles and users (?history, workflow names, notify text) is data: printed
        // escaped, so no ESC, BEL or C1 control in it reaches this terminal (issue 23, item 8).
        String text = Printable.escape(f.replyText());
        if (f.status() == Status.ERROR) {
            err.println("Error: " + text + " [" + f.errorCode() + ", " + f.serviceId() + "]");
            return;
        }
        if (f.status() == Status.PROGRESS) {
            if (f.result() instanceof Progress p) {
                err.println("  ... " + Printable.escape(progressLine(p)));
            } else {
                err.println("  ... " + text);
            }
            return;
        }
        if (f.result() instanceof TableResult t) {
            if (!text.isEmpty()) {
                out.println(text);
            }
            out.print(Printable.escape(table(t)));
        } else if (f.result() instanceof ImageResult img) {
            out.println(text.isEmpty() ? "image " + Printable.escape(img.name()) + " (" + img.jpeg().length + " bytes)" : text);
        } else if (!text.isEmpty()) {
            out.println(text);
        } else if (f.result() != null) {
            out.println(Printable.escape(String.valueOf(f.result())));
        }
    }

    /** {@code receiving MISSION1.LOG 20000/50000 (40%) 11.2 kB/s ETA 0:03}: what is known of it. */
    static String progressLine(Progress p) {
        return p.what() + " " + p.done() + (p.total() > 0 ? "/" + p.total() : "")
                + (p.percent() >= 0 ? " (" + p.percent() + "%)" : "")
                + (p.rateText().isEmpty() ? "" : " " + p.rateText())
                + (p.etaText().isEmpty() ? "" : " ETA " + p.etaText());
    }

    static String table(TableResult t) {
        int n = t.columns().size();
        int[] width = new int[n];
        for (int i = 0; i < n; i++) {
            width[i] = Math.min(MAX_CELL, t.columns().get(i).length());
        }
        for (String[] row : t.rows()) {
            for (int i = 0; i < n; i++) {
                width[i] = Math.max(width[i], Math.min(MAX_CELL, cell(row[i]).length()));
            }
        }
        StringBuilder b = new StringBuilder();
        line(b, t.columns().toArray(new String[0]), width);
        List<String> rule = new ArrayList<>();
        for (int w : width) {
            rule.add("-".repeat(w));
        }
        line(b, rule.toArray(new String[0]), width);
        for (String[] row : t.rows()) {
            line(b, row, width);
        }
        b.append('(').append(t.rows().size()).append(t.rows().size() == 1 ? " row" : " rows")
                .append(t.truncated() ? ", truncated at the service's limit" : "").append(")\n");
        return b.toString();
    }

    private static void line(StringBuilder b, String[] cells, int[] width) {
        for (int i = 0; i < cells.length; i++) {
            String c = cell(cells[i]);
            if (c.length() > MAX_CELL) {
                c = c.substring(0, MAX_CELL - 1) + "…";
            }
            b.append(i == 0 ? "" : " | ").append(c).append(" ".repeat(Math.max(0, width[i] - c.length())));
        }
        b.append('\n');
    }

    private static String cell(String v) {
        return v == null ? "NULL" : v.replace('\n', ' ').replace('\r', ' ');
    }

    static Map<String, Object> toMap(OutgoingServerMessage reply) {
        Map<String, Object> m = new LinkedHashMap<>();
        var h = reply.header();
        var f = reply.footer();
        m.put("id", h.messageId());
        m.put("status", f.status().name());
        m.put("serviceId", f.serviceId());
        if (f.status() == Status.ERROR) {
            m.put("error", f.errorCode().name());
        }
        m.put("mailbox", h.mailboxAddress());
        m.put("command", h.body().startsWith("?upload") || h.body().startsWith("?login") ? h.body().split(" ")[0] : h.body());
        m.put("text", f.replyText());
        m.put("route", f.route());
        Result r = f.result();
        if (r != null) {
            m.put("result", result(r));
        }
        return m;
    }

    private static Object result(Result r) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("type", r.getClass().getSimpleName());
        if (r instanceof TableResult t) {
            m.put("columns", t.columns());
            m.put("types", t.types());
            List<Object> rows = new ArrayList<>();
            t.rows().forEach(row -> rows.add(Cells.row(t.types(), row))); // numbers as numbers, NULL as null
            m.put("rows", rows);
            m.put("truncated", t.truncated());
        } else if (r instanceof FileListing l) {
            m.put("directory", l.directory());
            List<Object> files = new ArrayList<>();
            for (FileListing.Entry e : l.files()) {
                files.add(Map.of("name", e.name(), "size", e.size(), "modified", Instant.ofEpochMilli(e.modified()).toString()));
            }
            m.put("files", files);
        } else if (r instanceof ServiceList s) {
            List<Object> list = new ArrayList<>();
            for (ServiceDescriptor d : s.services()) {
                list.add(Map.of("name", d.name(), "sid", d.sid(), "description", d.description(), "panel", d.panel()));
            }
            m.put("services", list);
        } else if (r instanceof MailboxList l) {
            List<Object> list = new ArrayList<>();
            l.mailboxes().forEach(s -> list.add(mailbox(s)));
            m.put("mailboxes", list);
        } else if (r instanceof MailboxStatus s) {
            m.putAll(mailbox(s));
        } else if (r instanceof Progress p) {
            m.put("what", p.what());
            m.put("done", p.done());
            m.put("total", p.total());
            m.put("rate", p.ratePerSecond());
            m.put("etaSeconds", p.etaSeconds());
        } else if (r instanceof ImageResult img) {
            m.put("name", img.name());
            m.put("bytes", img.jpeg().length);
        } else if (r instanceof UpdateCount u) {
            m.put("count", u.count());
        } else if (r instanceof SessionInfo s) {
            m.put("clientId", s.clientId());
            m.put("user", s.user());
            m.put("roles", s.roles());
        } else {
            m.put("value", r.toString());
        }
        return m;
    }

    private static Map<String, Object> mailbox(MailboxStatus s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("address", s.address());
        m.put("available", s.available());
        m.put("running", s.running());
        m.put("busy", s.busy());
        m.put("lockedBy", s.lockedBy());
        m.put("detail", s.detail());
        return m;
    }
}
