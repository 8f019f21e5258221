package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 34 as launched: the server, the glider simulator, a SerialPortServer and a DatabaseServer,
 * each {@code java -jar} of its own. A fetched Slocum file is ingested with its bytes going from the
 * SerialPortServer to the DatabaseServer by handout ticket: the server process writes them once (its
 * download copy), which the kernel's count of the bytes it wrote ({@code /proc/PID/io} wchar) shows.
 * Then a SerialPortServer that holds nothing for handouts ({@code -Dripv.handout.maxBytes=0}): the
 * DatabaseServer's read is refused, the server relays the bytes as before — it writes them twice —
 * and the user sees the same verdict both times.
 */
class HandoutEndToEndTest {
    static final Path ROOT = LaunchedSystem.ROOT;
    static final String FILE = "unit_363_2013_245_6_6.mrg";

    @TempDir
    Path tmp;

    @RegisterExtension
    final LaunchedSystem sys = new LaunchedSystem();

    /** The bytes a process has written so far (files, sockets, pipes), as the kernel counts them. */
    static long written(Process p) throws Exception {
        for (String line : Files.readAllLines(Path.of("/proc/" + p.pid() + "/io"))) {
            if (line.startsWith("wchar:")) {
                return Long.parseLong(line.substring(6).strip());
            }
        }
        throw new IllegalStateException("no wchar in /proc/" + p.pid() + "/io");
    }

    /** The serial MailBox of the SerialPortServer registered as {@code host}, once the DatabaseServer is there too. */
    String awaitSerial(String host) throws Exception {
        String prefix = "<SerialPortServer>::<" + host + ">";
        String boxes = sys.awaitAnswer("?mailboxes", t -> t.contains("<DatabaseServer>")
                && LaunchedSystem.MAILBOX.matcher(t).results().anyMatch(r -> r.group().startsWith(prefix)), LaunchedSystem.STARTUP);
        return LaunchedSystem.MAILBOX.matcher(boxes).results().map(r -> r.group()).filter(s -> s.startsWith(prefix))
                .findFirst().orElseThrow();
    }

    /** Fetches the file and returns how many bytes the server process wrote meanwhile. */
    long fetch(Process server, String serial) throws Exception {
        long before = written(server);
        assertThat(sys.cli("use " + serial, "ymodem:get " + FILE)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("received " + FILE).contains("fetched 1, ingested").contains("into <DatabaseServer>");
        Thread.sleep(500); // the last log lines
        return written(server) - before;
    }

    @Test
    void theServerNeverSendsTheFetchedBytesOnWhenTheServicesReachEachOther() throws Exception {
        LaunchedSystem.assumeJars();
        assumeTrue(Files.isReadable(Path.of("/proc/self/io")), "needs Linux's /proc/PID/io");
        Path data = sys.data;
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        Path source = ROOT.resolve("ripv-services/src/test/resources/slocum").resolve(FILE);
        Files.copy(source, files.resolve(FILE));
        long size = Files.size(source);

        Process server = sys.startServer(List.of());
        sys.startSimulator("--listen", "" + sys.gliderPort, "--files", files.toString());
        sys.startService("database", List.of(), "database");
        Process direct = sys.startService("serial-direct", List.of(), "serial", "--no-enumerate",
                "--link", "tcp://127.0.0.1:" + sys.gliderPort);
        String serial = awaitSerial("localhost");

        long handedOver = fetch(server, serial);
        assertThat(sys.out()).contains("fetched 1, ingested 1 into <DatabaseServer>");
        assertThat(sys.log("database")).as(sys.log("database")).contains("from the services that fetched it");
        assertThat(sys.log("server")).contains("reads the bytes from <SerialPortServer>::<localhost>").doesNotContain("relaying");
        // the download copy is written once; nothing near the file's size besides
        assertThat(handedOver).as("bytes the server wrote while the file was fetched and ingested (the file: " + size + ")")
                .isGreaterThanOrEqualTo(size).isLessThan(size + size / 2);
        Path stored;
        try (var found = Files.walk(data.resolve("download"))) {
            stored = found.filter(f -> f.getFileName().toString().equals(FILE)).findFirst().orElseThrow();
        }
        assertThat(Files.readAllBytes(stored)).isEqualTo(Files.readAllBytes(source)); // the user's copy, whole

        // A SerialPortServer that holds nothing: the DatabaseServer's read is refused, the server relays.
        direct.destroy();
        assertThat(direct.waitFor(20, TimeUnit.SECONDS)).isTrue();
        sys.startService("serial-relay", List.of("-Dripv.handout.maxBytes=0"), "serial", "--host", "127.0.0.1",
                "--no-enumerate", "--link", "tcp://127.0.0.1:" + sys.gliderPort); // another name, same host
        String relaySerial = awaitSerial("127.0.0.1");
        long relayed = fetch(server, relaySerial);
        assertThat(sys.out()).contains("stored already"); // the same file: the database says so, a note of an OK fetch
        assertThat(sys.log("server")).contains("relaying " + size + " bytes to <DatabaseServer>").contains("handout refused");
        assertThat(sys.log("database")).contains("no longer holds the file");
        System.out.printf("server wrote %d bytes handing over and %d relaying a file of %d bytes%n", handedOver, relayed, size);
        assertThat(relayed).as("bytes the server wrote while it relayed the file (the file: " + size + ")")
                .isGreaterThanOrEqualTo(2 * size);
        assertThat(sys.log("database") + sys.log("serial-direct") + sys.log("serial-relay")).doesNotContain("REJECTED");
    }
}
