package org.ripv.probe;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.ServerSocket;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

class FreePortsTest {
    @Test
    void portsAreDifferentBindableAndOutsideTheKernelsOwnRange() throws Exception {
        int[] ports = FreePorts.several(40);
        assertThat(Arrays.stream(ports).distinct().count()).isEqualTo(40);
        int ephemeral = FreePorts.ephemeralStart();
        for (int p : ports) {
            if (ephemeral > 12_000) {
                assertThat(p).isBetween(10_000, ephemeral - 1);
            }
            try (ServerSocket s = new ServerSocket(p)) {
                assertThat(s.getLocalPort()).isEqualTo(p);
            }
        }
    }

    @Test
    void aPortInUseIsPassedOver() throws Exception {
        int first = FreePorts.one();
        // The walk goes up one at a time: hold the next few, and none of them comes back.
        ServerSocket[] held = new ServerSocket[3];
        try {
            for (int i = 0; i < held.length; i++) {
                try {
                    held[i] = new ServerSocket(first + 1 + i);
                } catch (java.net.BindException alreadyInUse) {
                    // someone else holds it: passed over all the same
                }
            }
            int next = FreePorts.one();
            assertThat(next).isNotIn(first + 1, first + 2, first + 3);
        } finally {
            for (ServerSocket s : held) {
                if (s != null) {
                    s.close();
                }
            }
        }
    }
}
