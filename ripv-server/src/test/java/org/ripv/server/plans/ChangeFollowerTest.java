package org.ripv.server.plans;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.plans.SurfacingFacts;
import org.ripv.server.files.FileStore;

/**
 * The follower's states from console entries as the server sees them (the to-vehicle round's
 * line, a workflow's end, the vehicle's echo, surfacings), and its book across a restart.
 */
class ChangeFollowerTest {
    static final String M = "<SerialPortServer>::<shore>ru29";
    /** The SHA-256 of the file {@link #sentLine} sends: 40 x's. */
    static final String SENT_SHA = java.util.HexFormat.of().formatHex(sha("x".repeat(40)));

    private static byte[] sha(String s) {
        try {
            return java.security.MessageDigest.getInstance("SHA-256").digest(s.getBytes(StandardCharsets.US_ASCII));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    @TempDir
    Path dir;
    FileStore files;
    ChangeBook book;
    List<ConsoleEntry> published = new ArrayList<>();
    ChangeFollower follower;

    @BeforeEach
    void setUp() throws Exception {
        files = new FileStore(dir.resolve("upload"), dir.resolve("download"), 1 << 20);
        book = new ChangeBook(dir.resolve("plans"));
        follower = new ChangeFollower(book, files, published::add);
    }

    private Change fileChange(long at) throws Exception {
        Change c = new Change(book.nextId(), M, Change.Kind.FILE, "goto_l10.ma", "", "goto_l11.ma", SENT_SHA, 40, "alice",
                Change.State.QUEUED, at, 0, 0, 0, 0, "to-vehicle/F/goto_l10.ma", 0, "",
                List.of(new double[] {41.5, -70.5}, new double[] {41.6, -70.4}));
        book.put(c);
        return c;
    }

    private Change setChange(long workflow, long at) throws Exception {
        Change c = new Change(book.nextId(), M, Change.Kind.SET, "c_dive_target_depth", "30", "put c_dive_target_depth 30", "", 0,
                "alice", Change.State.QUEUED, at, 0, 0, 0, 0, "workflow " + workflow, workflow, "", List.of());
        book.put(c);
        return c;
    }

    private static ConsoleEntry at(long t, ConsoleEntry e) {
        return new ConsoleEntry(t, e.mailbox(), e.kind(), e.user(), e.text(), e.event(), e.lat(), e.lon());
    }

    private Change.State state(long id) {
        return book.of(M).stream().filter(c -> c.id() == id).findFirst().orElseThrow().state();
    }

    private void sentLine(long t) throws Exception {
        Path sent = Files.createDirectories(dir.resolve("upload/to-vehicle/F/sent")).resolve("goto_l10.ma");
        Files.writeString(sent, "x".repeat(40), StandardCharsets.US_ASCII);
        follower.take(at(t, ConsoleEntry.command(M, "alice", "to-vehicle: sent goto_l10.ma (40 bytes) in 0.1 s by ZMODEM; the"
                + " vehicle's dir lists goto_l10.ma with 40 bytes; moved to to-vehicle/F/sent/goto_l10.ma (receipt"
                + " to-vehicle/F/sent/goto_l10.ma.receipt)")));
    }

    @Test
    void aGotoFileIsSentReceivedAndInEffectWhenALaterDialogSteersForOneOfItsWaypoints() throws Exception {
        Change c = fileChange(1000);
        sentLine(2000);
        assertThat(state(c.id())).isEqualTo(Change.State.RECEIVED);
        Change now = book.of(M).get(0);
        assertThat(now.detail()).contains("sha256 " + SENT_SHA);
        // the call on which it arrived does not count; a later one does
        follower.judge(new SurfacingFacts(M, 1500, Map.of(), 41.0, -70.0));
        assertThat(state(c.id())).isEqualTo(Change.State.RECEIVED);
        follower.judge(new SurfacingFacts(M, 3000, Map.of(), 41.60001, -70.40001));
        assertThat(state(c.id())).isEqualTo(Change.State.IN_EFFECT);
        assertThat(published).extracting(ConsoleEntry::text).anySatisfy(t -> assertThat(t).contains("in effect")
                .contains("is waypoint 1"));
        assertThat(new ChangeBook(dir.resolve("plans")).of(M)).extracting(Change::state).containsExactly(Change.State.IN_EFFECT);
    }

    @Test
    void aFileTheRoundSentThatIsNotTheOneCheckedCancelsItsChange() throws Exception {
        Change c = staged(withStaged(fileChange(1000), "to-vehicle/F/goto_l10.ma", "0".repeat(64)));
        sentLine(2000);
        assertThat(state(c.id())).isEqualTo(Change.State.CANCELLED);
        assertThat(book.of(M).get(0).detail()).contains("not the file checked").contains("sha256 " + SENT_SHA);
    }

    @Test
    void twoSurfacingsWithoutItAreNotInEffectWithOneAlert() throws Exception {
        Change c = fileChange(1000);
        sentLine(2000);
        follower.judge(new SurfacingFacts(M, 3000, Map.of(), 41.0, -70.0));
        assertThat(state(c.id())).isEqualTo(Change.State.RECEIVED);
        assertThat(book.of(M).get(0).detail()).contains("1 of 2").contains("none of the file's 2 waypoints");
        follower.judge(SurfacingFacts.of(M, 4000, Map.of("m_battery", 15.0)));
        assertThat(state(c.id())).isEqualTo(Change.State.NOT_IN_EFFECT);
        assertThat(book.of(M).get(0).detail()).contains("no c_wpt_lat/lon in its dialog");
        follower.judge(new SurfacingFacts(M, 5000, Map.of(), 41.5, -70.5));
        assertThat(state(c.id())).isEqualTo(Change.State.NOT_IN_EFFECT);
        assertThat(published).filteredOn(e -> e.event() == VehicleEvent.ALERT).hasSize(1);
    }

    @Test
    void aPutIsSentByItsWorkflowReceivedByItsEchoAndInEffectWhenTheDialogShowsTheValue() throws Exception {
        Change other = setChange(6, 500);
        Change c = setChange(7, 1000);
        follower.take(at(1500, ConsoleEntry.event(M, VehicleEvent.SURFACED, "call 1", null, null)));
        follower.take(at(1600, ConsoleEntry.line(M, "   sensor:c_dive_target_depth=30")));
        follower.take(at(1700, ConsoleEntry.event(M, VehicleEvent.WORKFLOW_FAILED, "workflow 6 'plan-set-x.wf': failed: …", null, null)));
        assertThat(state(other.id())).isEqualTo(Change.State.QUEUED);
        follower.take(at(1800, ConsoleEntry.event(M, VehicleEvent.WORKFLOW_DONE, "workflow 7 'plan-set-c_dive_target_depth.wf': done",
                null, null)));
        assertThat(state(c.id())).isEqualTo(Change.State.RECEIVED);
        follower.judge(SurfacingFacts.of(M, 2500, Map.of("c_dive_target_depth", 30.0)));
        assertThat(state(c.id())).isEqualTo(Change.State.IN_EFFECT);
    }

    @Test
    void theParsedDialogsSensorsMakeTheFactsWithTheWaypointAsDegreesAndMinutes() {
        java.util.List<org.ripv.surfacing.Surfacing> got = new ArrayList<>();
        org.ripv.surfacing.SurfaceDialogParser p = new org.ripv.surfacing.SurfaceDialogParser(got::add);
        p.feed("Glider ru29 at surface.\r\nBecause:Surface interval [1]\r\n   sensor:c_wpt_lat(lat)=4136.000\r\n"
                + "   sensor:C_WPT_LON(lon)=-7024.000    12.0 secs ago\r\n   sensor:m_battery(volts)=15.1\r\n"
                + "Hit Control-C within 10 seconds to abort the mission\r\n");
        assertThat(got).hasSize(1);
        SurfacingFacts f = Plans.facts(M, 1000, got.get(0));
        assertThat(f.time()).isEqualTo(1000);
        assertThat(f.wptLat()).isCloseTo(41.6, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(f.wptLon()).isCloseTo(-70.4, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(f.sensors()).containsEntry("m_battery", 15.1);
        assertThat(SurfacingFacts.of(M, 0, Map.of("c_wpt_lat", 69696969.0)).wptLat()).isNull();
    }

    @Test
    void aQueuedFileWhoseStagedCopyIsDeletedOrReplacedIsCancelledButOneTheRoundJustSentIsNot() throws Exception {
        Path folder = Files.createDirectories(files.uploadDir().resolve("to-vehicle/F"));
        Files.writeString(folder.resolve("goto_l10.ma"), "checked");
        String sha = ChangeFollower.sha256(folder.resolve("goto_l10.ma"));
        Change deleted = staged(withStaged(fileChange(1000), "to-vehicle/F/goto_l10.ma", sha));
        Files.writeString(folder.resolve("goto_l12.ma"), "checked");
        Change replaced = staged(withStaged(fileChange(1000), "to-vehicle/F/goto_l12.ma", sha));
        Files.writeString(folder.resolve("goto_l13.ma"), "checked");
        Change kept = staged(withStaged(fileChange(1000), "to-vehicle/F/goto_l13.ma", sha));
        Change justSent = staged(withStaged(fileChange(System.currentTimeMillis()), "to-vehicle/F/goto_l14.ma", sha));
        Files.createDirectories(folder.resolve("sent"));
        Files.writeString(folder.resolve("sent/goto_l14.ma.receipt"), "file: to-vehicle/F/goto_l14.ma\nbytes: 7\n");

        Files.delete(folder.resolve("goto_l10.ma"));
        Files.writeString(folder.resolve("goto_l12.ma"), "another file");
        follower.take(at(2000, ConsoleEntry.event(M, VehicleEvent.SURFACED, "call 1", null, null)));

        assertThat(state(deleted.id())).isEqualTo(Change.State.CANCELLED);
        assertThat(book.of(M).stream().filter(c -> c.id() == deleted.id()).findFirst().orElseThrow().detail())
                .contains("was deleted before a call took it");
        assertThat(state(replaced.id())).isEqualTo(Change.State.CANCELLED);
        assertThat(state(kept.id())).isEqualTo(Change.State.QUEUED);
        assertThat(state(justSent.id())).isEqualTo(Change.State.QUEUED);
        assertThat(published).filteredOn(e -> e.event() == VehicleEvent.PLAN_CHANGE && e.text().contains(": cancelled: ")).hasSize(2);
        assertThat(Change.State.CANCELLED.settled()).isTrue();
        assertThat(new ChangeBook(dir.resolve("plans")).of(M)).filteredOn(c -> c.state() == Change.State.CANCELLED).hasSize(2);
    }

    private Change staged(Change c) throws Exception {
        book.put(c);
        return c;
    }

    private static Change withStaged(Change c, String staged, String sha) {
        return new Change(c.id(), c.mailbox(), c.kind(), c.target(), c.value(), c.source(), sha, c.bytes(), c.user(), c.state(),
                c.queuedAt(), c.sentAt(), c.receivedAt(), c.settledAt(), c.surfacings(), staged, c.workflowId(), c.detail(),
                c.waypoints());
    }
}
