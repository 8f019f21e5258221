package org.ripv.rmi;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The launchers' filter factory, in a JVM of its own as a launched server or service has it:
 * hostile RMI replies and arguments are refused, while a library's own object streams (Derby's
 * {@code boolean[]} while it creates tables, issue 22) are left to the JVM.
 */
class RmiStreamFiltersTest {
    @Test
    void rmiAndRipvStreamsAreAllowlistedAndALibrarysOwnStreamsAreNot() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), RmiStreamFiltersProbe.class.getName())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        assertThat(out).as(out)
                .contains("installed true again true")
                .contains("library boolean[] read boolean[]")
                .contains("library HashMap read HashMap")
                .contains("ripv HashMap refused InvalidClassException")
                .contains("ripv boolean[] read boolean[]") // arrays of primitives are data (WireFilter.forProcess)
                .contains("rmi heartbeat true")
                .contains("rmi hostile reply refused InvalidClassException")
                .contains("rmi hostile argument refused")
                .contains("delivered false");
    }

    @Test
    void onlyRmisAndRipvsOwnClassesCountAsMakersOfAllowlistedStreams() {
        assertThat(RmiStreamFilters.isRipvOrRmi("sun.rmi.server.MarshalInputStream")).isTrue();
        assertThat(RmiStreamFilters.isRipvOrRmi("sun.rmi.transport.ConnectionInputStream")).isTrue();
        assertThat(RmiStreamFilters.isRipvOrRmi("org.ripv.wire.FrameCodec")).isTrue();
        assertThat(RmiStreamFilters.isRipvOrRmi("org.apache.derby.iapi.services.io.FormatIdInputStream")).isFalse();
        assertThat(RmiStreamFilters.isRipvOrRmi(null)).isFalse();
    }
}
