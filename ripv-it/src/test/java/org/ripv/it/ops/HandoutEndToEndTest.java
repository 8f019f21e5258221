package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine;

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
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final String FILE = "unit_363_2013_245_6_6.mrg";

    @TempDir
    Path tmp;
    final List<Process> started = new ArrayList<>();
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    int clientPort;

    Process launch(String name, String module, List<String> jvm, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(org.ripv.it.TestJvms.java(),
                "-Xmx256m", "-Duser.home=" + tmp.resolve("home")));
        cmd.addAll(jvm);
        cmd.addAll(List.of("-jar", LaunchedDataLoopTest.jar(module).toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(tmp.toFile()).redirectErrorStream(true)
                .redirectOutput(tmp.resolve(name + ".log").toFile());
        pb.environment().put("HOME", tmp.resolve("home").toString());
        Process p = pb.start();
        started.add(p);
        return p;
    }

    String log(String name) throws Exception {
        Path f = tmp.resolve(name + ".log");
        return Files.exists(f) ? Files.readString(f, StandardCharsets.UTF_8) : "";
    }

    @AfterEach
    void stop() throws Exception {
        for (int i = started.size() - 1; i >= 0; i--) {
            started.get(i).destroy();
        }
        for (Process p : started) {
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }

    int cli(String... lines) {
        out.reset();
        List<String> all = new ArrayList<>(List.of("--server", "localhost:" + clientPort, "--user", "alice",
                "--password", TestSystem.PASSWORD, "--timeout", "120", "--known-hosts", tmp.resolve("known_hosts").toString()));
        for (String l : lines) {
            all.add("--exec");
            all.add(l);
        }
        PrintStream p = new PrintStream(out, true, StandardCharsets.UTF_8);
        return new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), p, p)).execute(all.toArray(String[]::new));
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

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
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (true) {
            cli("?mailboxes");
            var m = LaunchedDataLoopTest.MAILBOX.matcher(out()).results().map(r -> r.group())
                    .filter(s -> s.startsWith("<SerialPortServer>::<" + host + ">")).findFirst();
            if (m.isPresent() && out().contains("<DatabaseServer>")) {
                return m.get();
            }
            assertThat(System.nanoTime()).as("services registered; last answer: " + out() + "\nlogs: " + log("serial-direct") + log("serial-relay")
                    + log("database")).isLessThan(end);
            Thread.sleep(500);
        }
    }

    /** Fetches the file and returns how many bytes the server process wrote meanwhile. */
    long fetch(Process server, String serial) throws Exception {
        long before = written(server);
        assertThat(cli("use " + serial, "ymodem:get " + FILE)).as(out()).isZero();
        assertThat(out()).as(out()).contains("received " + FILE).contains("fetched 1, ingested").contains("into <DatabaseServer>");
        Thread.sleep(500); // the last log lines
        return written(server) - before;
    }

    @Test
    void theServerNeverSendsTheFetchedBytesOnWhenTheServicesReachEachOther() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(LaunchedDataLoopTest.jar(m)), "needs the jars (mvn package builds them)");
        }
        assumeTrue(Files.isReadable(Path.of("/proc/self/io")), "needs Linux's /proc/PID/io");
        int[] p = LaunchedDataLoopTest.freePorts(4);
        clientPort = p[0];
        Path data = tmp.resolve("ripv-data");
        Files.createDirectories(tmp.resolve("home"));
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        Path source = ROOT.resolve("ripv-services/src/test/resources/slocum").resolve(FILE);
        Files.copy(source, files.resolve(FILE));
        long size = Files.size(source);

        Process server = launch("server", "ripv-server", List.of(), "server", "--data", data.toString(), "--port", "" + p[0],
                "--registry-port", "" + p[1], "--http-port", "0", "--outbound-port", "" + p[2]);
        launch("simulator", "ripv-services", List.of(), "simulator", "--listen", "" + p[3], "--files", files.toString());
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!log("server").contains("RIPVServer ready")) {
            assertThat(System.nanoTime()).as(log("server")).isLessThan(end);
            assertThat(server.isAlive()).as(log("server")).isTrue();
            Thread.sleep(200);
        }
        PermitFile.setUser(data.resolve("permit.txt"), "alice", TestSystem.PASSWORD.toCharArray(), List.of("operators"), 1000);
        String secret = data.resolve("service.secret").toString();
        String at = "localhost:" + p[1];
        launch("database", "ripv-services", List.of(), "database", "--server", at, "--secret-file", secret);
        Process direct = launch("serial-direct", "ripv-services", List.of(), "serial", "--server", at, "--secret-file", secret,
                "--no-enumerate", "--link", "tcp://127.0.0.1:" + p[3]);
        String serial = awaitSerial("localhost");

        long handedOver = fetch(server, serial);
        assertThat(out()).contains("fetched 1, ingested 1 into <DatabaseServer>");
        assertThat(log("database")).as(log("database")).contains("from the services that fetched it");
        assertThat(log("server")).contains("reads the bytes from <SerialPortServer>::<localhost>").doesNotContain("relaying");
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
        launch("serial-relay", "ripv-services", List.of("-Dripv.handout.maxBytes=0"), "serial", "--server", at, "--secret-file",
                secret, "--host", "127.0.0.1", "--no-enumerate", "--link", "tcp://127.0.0.1:" + p[3]); // another name, same host
        String relaySerial = awaitSerial("127.0.0.1");
        long relayed = fetch(server, relaySerial);
        assertThat(out()).contains("stored already"); // the same file: the database says so, a note of an OK fetch
        assertThat(log("server")).contains("relaying " + size + " bytes to <DatabaseServer>").contains("handout refused");
        assertThat(log("database")).contains("no longer holds the file");
        System.out.printf("server wrote %d bytes handing over and %d relaying a file of %d bytes%n", handedOver, relayed, size);
        assertThat(relayed).as("bytes the server wrote while it relayed the file (the file: " + size + ")")
                .isGreaterThanOrEqualTo(2 * size);
        assertThat(log("database") + log("serial-direct") + log("serial-relay")).doesNotContain("REJECTED");
    }
}
