package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 24, item 4: the glider simulator launched as its own process ({@code ripv-services.jar
 * simulator --call … --dialog gliderdos}) calls a shore port this test holds, and the test plays
 * the pilot with raw bytes: the countdown resumes the mission when nobody answers, Ctrl-E and
 * Ctrl-F answer, Ctrl-C gives the GliderDOS prompt, put / report / get / sequence / exit /
 * callback do what they say across calls, and zs / zr move files with lrzsz's rz / sz on this side.
 * The second test calls over the Iridium-like line: paced, and dropped, then dialled again.
 */
class GliderDosEndToEndTest {
    static final String PROMPT = "GliderDOS I -3 >";

    @TempDir
    Path dir;
    Process simulator;
    ServerSocket shore;

    @AfterEach
    void stop() throws Exception {
        SimulatorProcess.stop(simulator);
        if (shore != null) {
            shore.close();
        }
    }

    private void launch(String... options) throws IOException {
        shore = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress());
        List<String> all = new ArrayList<>(List.of("--call", "127.0.0.1:" + shore.getLocalPort(), "--name", "ru29",
                "--dir", dir.resolve("glider").toString()));
        all.addAll(List.of(options));
        simulator = SimulatorProcess.start(dir.resolve("simulator.log"), all);
    }

    /** One call: the socket the glider dialled and what it has said so far. */
    static final class Call implements AutoCloseable {
        final Socket socket;
        final InputStream in;
        final OutputStream out;
        final StringBuilder said = new StringBuilder();
        /** Where the next {@link #until} starts looking, when lrzsz gave back what it was handed after its transfer. */
        int mark = -1;

        Call(Socket socket) throws IOException {
            this.socket = socket;
            this.in = socket.getInputStream();
            this.out = socket.getOutputStream();
        }

        /** Reads until {@code text} has been said (since the last mark), within 60 s; returns what came. */
        String until(String text) throws IOException {
            int from = mark >= 0 ? mark : said.length();
            mark = -1;
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            byte[] buf = new byte[4096];
            while (said.indexOf(text, from) < 0) {
                if (System.nanoTime() > end) {
                    throw new AssertionError("never said '" + text + "'; said:\n" + said.substring(from));
                }
                socket.setSoTimeout(1000);
                try {
                    int n = in.read(buf);
                    if (n < 0) {
                        throw new EOFException("hung up before '" + text + "'; said:\n" + said.substring(from));
                    }
                    said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
                } catch (SocketTimeoutException e) {
                    // keep waiting
                }
            }
            return said.substring(from);
        }

        /** Reads until the glider hangs up; returns what it said meanwhile. */
        String untilHangUp() throws IOException {
            int from = said.length();
            byte[] buf = new byte[4096];
            socket.setSoTimeout(60_000);
            for (int n; (n = in.read(buf)) > 0; ) {
                said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            }
            return said.substring(from);
        }

        void key(int b) throws IOException {
            out.write(b);
            out.flush();
        }

        String command(String line, String waitFor) throws IOException {
            out.write((line + "\r\n").getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            return until(waitFor);
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    private Call accept() throws IOException {
        shore.setSoTimeout(60_000);
        return new Call(shore.accept());
    }

    @Test
    void theSurfaceDialogTheKeysAndGliderDosAsAPilotMeetsThem() throws Exception {
        Files.createDirectories(dir.resolve("glider"));
        Files.writeString(dir.resolve("glider/goto_l10.ma"), "behavior_name=goto_list\n");
        Files.writeString(dir.resolve("glider/NIGHT.MI"), "# the night's mission\n");
        byte[] sensor = new byte[30_000];
        new Random(24).nextBytes(sensor);
        Files.write(dir.resolve("glider/SENSOR.DAT"), sensor);
        launch("--dialog", "gliderdos", "--surface-seconds", "4", "--dive-seconds", "1", "--minute-seconds", "2");

        // call 1: nobody answers, and the mission resumes on its own
        try (Call c = accept()) {
            String all = c.untilHangUp();
            assertThat(all).contains("Glider ru29 at surface.").contains("MissionName:SIM.MI MissionNum:ru29-1")
                    .contains("Hit Control-R to RESUME the mission, or Control-C to abort it")
                    .contains("Hit Control-C within 4 seconds to abort the mission...")
                    .contains("No answer: resuming the mission.").contains("Hanging up: diving for 1 s")
                    .doesNotContain(PROMPT);
        }

        // call 2: Ctrl-E and Ctrl-F answer during the countdown, Ctrl-C gives GliderDOS
        try (Call c = accept()) {
            c.until("seconds to abort the mission...");
            c.key(0x05);
            assertThat(c.until("Surface time extended by 4 s")).contains("^E");
            c.key(0x06);
            assertThat(c.until("file(s)")).contains("Re-read the mafiles: 1 file(s)");
            c.key(0x03);
            assertThat(c.until(PROMPT)).contains("^C");
            assertThat(c.command("put c_dive_target_depth 30", PROMPT)).contains("sensor:c_dive_target_depth=30");
            assertThat(c.command("put c_dive_target_depth deep", PROMPT)).contains("'deep' is not a number");
            assertThat(c.command("report ++ c_dive_target_depth", PROMPT)).contains("sensor:c_dive_target_depth=30");
            assertThat(c.command("report list", PROMPT)).contains("report list: c_dive_target_depth");
            assertThat(c.command("get c_dive_target_depth", PROMPT)).contains("c_dive_target_depth=30");
            assertThat(c.command("sequence", PROMPT)).contains("sequence: SIM.MI");
            assertThat(c.command("sequence NOPE.MI", PROMPT)).contains("no mission file NOPE.MI");
            assertThat(c.command("exit", "C:\\>")).contains("Exiting GliderDOS to PicoDOS");
            assertThat(c.command("dir", "C:\\>")).contains("SENSOR.DAT").contains("NIGHT.MI");
            c.command("gliderdos", PROMPT);

            // zs: the glider's sz sends, lrzsz's rz receives here
            Path here = Files.createDirectories(dir.resolve("shore"));
            c.command("zs sensor.dat", "zs sensor.dat\r\n");
            assertThat(Lrzsz.run(c, here, "rz", "-b", "-y")).as("rz exit").isZero();
            assertThat(c.until(PROMPT)).contains("1 file(s) sent");
            assertThat(Files.readAllBytes(here.resolve("SENSOR.DAT"))).isEqualTo(sensor);

            // zr: sz sends from here, the glider's rz receives
            byte[] mission = "waypoints 41.5 -70.6\n".repeat(3000).getBytes(StandardCharsets.US_ASCII);
            Files.write(here.resolve("goto_l11.ma"), mission);
            c.command("zr", "zr\r\n");
            assertThat(Lrzsz.run(c, here, "sz", "-b", "goto_l11.ma")).as("sz exit").isZero();
            assertThat(c.until(PROMPT)).contains("file(s) received");
            assertThat(Files.readAllBytes(dir.resolve("glider/goto_l11.ma"))).isEqualTo(mission);

            // sequence runs the mission: the call ends with a dive
            assertThat(c.command("sequence night.mi", "Hanging up")).contains("Mission NIGHT.MI sequenced");
            c.untilHangUp();
        }

        // call 3: the new mission and the report list are in the dialog; Ctrl-R resumes at once
        try (Call c = accept()) {
            String dialog = c.until("seconds to abort the mission...");
            assertThat(dialog).contains("MissionName:NIGHT.MI MissionNum:ru29-3").contains("sensor:c_dive_target_depth=30");
            c.key(0x12);
            assertThat(c.untilHangUp()).contains("^R").contains("Resuming the mission.").contains("Hanging up: diving for 1 s");
        }

        // call 4: callback 1 hangs up and calls again after a (2 s) minute, without diving
        long hungUp;
        try (Call c = accept()) {
            c.until("seconds to abort the mission...");
            c.key(0x03);
            c.until(PROMPT);
            assertThat(c.command("callback 0", PROMPT)).contains("usage: callback MINUTES");
            c.command("callback 1", "calling back in 1 minute(s)");
            assertThat(c.untilHangUp()).doesNotContain("diving");
            hungUp = System.nanoTime();
        }
        try (Call c = accept()) {
            assertThat(System.nanoTime() - hungUp).as("called back after its minute").isGreaterThan(TimeUnit.MILLISECONDS.toNanos(1500));
            assertThat(c.until("seconds to abort the mission...")).contains("MissionNum:ru29-5");
            // at the GliderDOS prompt, --surface-seconds without input resumes the mission too
            c.key(0x03);
            c.until(PROMPT);
            assertThat(c.untilHangUp()).contains("No input for 4 s: resuming the mission.").contains("Hanging up: diving");
        }
    }

    @Test
    void anIridiumLikeCallIsPacedAndDropsAndTheGliderDialsAgain() throws Exception {
        // 1,200 baud is 120 bytes a second; the dialog and the keys are about 800 bytes
        launch("--dialog", "gliderdos", "--surface-seconds", "60", "--baud", "1200", "--latency", "500ms",
                "--drop-after", "4s");
        long t0;
        String first;
        try (Call c = accept()) {
            t0 = System.nanoTime();
            first = c.untilHangUp();
        }
        long took = System.nanoTime() - t0;
        assertThat(first).contains("Glider ru29 at surface.").doesNotContain("Hanging up");
        assertThat(took).as("dropped after about 4 s").isGreaterThan(TimeUnit.MILLISECONDS.toNanos(3500));
        // paced: in 4 s at 120 bytes a second, at most about 500 bytes crossed (and no dive: it dials again)
        assertThat(first.length()).as(first).isLessThan(600).isGreaterThan(100);
        try (Call c = accept()) {
            assertThat(c.until("MissionNum:ru29-2")).contains("Glider ru29 at surface.");
        }
    }

    /** lrzsz on the shore side, its standard input and output wired to the call's socket. */
    static final class Lrzsz {
        static int run(Call c, Path cwd, String... cmd) throws Exception {
            assumeTrue(Files.isExecutable(Path.of("/usr/bin/" + cmd[0])), "lrzsz is not installed");
            Process p = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
            Thread out = new Thread(() -> {
                try {
                    p.getInputStream().transferTo(c.out);
                } catch (IOException e) {
                    // the call or the process ended
                }
            }, "test-" + cmd[0] + "-out");
            out.start();
            c.mark = c.said.length();
            ByteArrayOutputStream handed = new ByteArrayOutputStream();
            byte[] buf = new byte[8192];
            c.socket.setSoTimeout(200);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            OutputStream toProcess = p.getOutputStream();
            while (p.isAlive() && System.nanoTime() < end) {
                try {
                    int n = c.in.read(buf);
                    if (n < 0) {
                        break;
                    }
                    try {
                        toProcess.write(buf, 0, n);
                        toProcess.flush();
                        handed.write(buf, 0, n);
                    } catch (IOException ended) {
                        c.said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1)); // after the transfer: the shell's
                    }
                } catch (SocketTimeoutException e) {
                    // keep pumping
                }
            }
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return -1;
            }
            out.join(5000);
            c.said.append(afterTheTransfer(handed.toString(StandardCharsets.ISO_8859_1)));
            return p.exitValue();
        }

        /**
         * What the glider said after its last ZFIN (and the sender's "OO"): the process had it in its
         * pipe when it exited, so it never reached the test though the glider printed it.
         */
        static String afterTheTransfer(String handed) {
            int fin = handed.lastIndexOf("**\u0018B08");
            if (fin < 0) {
                return "";
            }
            int at = Math.min(handed.length(), fin + 4 + 14); // "**", ZDLE, 'B', then type, flags and CRC in hex
            int oo = handed.indexOf("OO", at);
            if (oo >= 0 && oo <= at + 4) {
                at = oo + 2;
            }
            while (at < handed.length() && "\r\n\u008a\u0011".indexOf(handed.charAt(at)) >= 0) {
                at++;
            }
            return handed.substring(at);
        }
    }
}
