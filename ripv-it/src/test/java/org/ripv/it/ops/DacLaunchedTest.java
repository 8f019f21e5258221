package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code ripv dac profiles} and {@code ripv dac check} as a user runs them: the launcher script
 * starting {@code ripv-services.jar}, on rosie_713's real pair from the shared data, with the
 * sample deployment metadata and QC configuration docs/dac.md uses; then bad metadata: exit 1,
 * the reason on standard error, nothing written.
 */
class DacLaunchedTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
    static final Path DATA = ROOT.resolve("../shared/data/slocum-binary").normalize();

    record Run(int exit, String output) {
    }

    static Run ripv(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        byte[] out = p.getInputStream().readAllBytes();
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8));
    }

    @Test
    void aCallsFilesBecomeCheckedProfileFiles(@TempDir Path out) throws Exception {
        assumeTrue(Files.isDirectory(DATA), "the shared Slocum data is not at " + DATA);
        String seg = DATA.resolve("realtime_raw/rosie_713-2019-166-0-157").toString();
        Run r = ripv("dac", "profiles", "--cache", DATA.resolve("cac").toString(), "--meta", "docs/samples/dac-deployment.json",
                "--qc", "docs/samples/dac-qc.yml", "--out", out.toString(), seg + ".tbd", seg + ".sbd");
        assertThat(r.exit()).as(r.output()).isZero();
        assertThat(r.output().lines().filter(l -> l.matches("rosie_713_20190620T\\d{6}Z_rt\\.nc: (dive|climb), .*QC temperature .*"))).hasSize(10);
        String[] files = out.toFile().list((d, n) -> n.endsWith("_rt.nc"));
        assertThat(files).hasSize(10);
        List<String> check = new ArrayList<>(List.of("dac", "check"));
        for (String f : files) {
            check.add(out.resolve(f).toString());
        }
        Run c = ripv(check.toArray(String[]::new));
        assertThat(c.exit()).as(c.output()).isZero();
        assertThat(c.output().lines().filter(l -> l.contains(": passes"))).hasSize(10);
    }

    @Test
    void badMetadataIsRefusedAndNothingIsWritten(@TempDir Path dir) throws Exception {
        assumeTrue(Files.isDirectory(DATA), "the shared Slocum data is not at " + DATA);
        Path meta = dir.resolve("meta.json");
        Files.writeString(meta, Files.readString(ROOT.resolve("docs/samples/dac-deployment.json")).replace("\"title\": \"rosie_713 June 2019\",", ""));
        Path out = dir.resolve("out");
        String seg = DATA.resolve("realtime_raw/rosie_713-2019-166-0-157").toString();
        Run r = ripv("dac", "profiles", "--cache", DATA.resolve("cac").toString(), "--meta", meta.toString(),
                "--out", out.toString(), seg + ".tbd", seg + ".sbd");
        assertThat(r.exit()).isEqualTo(1);
        assertThat(r.output()).contains("Error: meta.json: 1 problem in the deployment metadata: global.title is missing");
        assertThat(Files.exists(out)).isFalse();
    }
}
