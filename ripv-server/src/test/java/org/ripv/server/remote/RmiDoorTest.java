package org.ripv.server.remote;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.net.ServerSocket;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.junit.jupiter.api.Test;

class RmiDoorTest {
    private static ServerRemote remote() {
        return new ServerRemote(null, null, null, null, (service, entries) -> { });
    }

    private static int free() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    @Test
    void aFreePortTakenBeforeTheRegistryBindsItIsReplacedByAnother() throws Exception {
        try (ServerSocket taken = new ServerSocket(0)) {
            Deque<Integer> ports = new ArrayDeque<>(List.of(taken.getLocalPort(), taken.getLocalPort()));
            int[] tried = {0};
            RmiDoor door = RmiDoor.openFree(null, remote(), () -> {
                tried[0]++;
                return ports.isEmpty() ? free() : ports.pop();
            });
            try {
                assertThat(tried[0]).isEqualTo(3);
                assertThat(door.port()).isNotEqualTo(taken.getLocalPort());
            } finally {
                door.close();
            }
        }
    }

    @Test
    void aPortAskedForByNumberIsNotSwappedWhenItIsTaken() throws IOException {
        try (ServerSocket taken = new ServerSocket(0)) {
            assertThatThrownBy(() -> RmiDoor.open(null, taken.getLocalPort(), remote()))
                    .hasMessageContaining("cannot open the RMI registry on port " + taken.getLocalPort());
        }
    }

    @Test
    void afterFiveTakenPortsItGivesUp() throws IOException {
        try (ServerSocket taken = new ServerSocket(0)) {
            int[] tried = {0};
            assertThatThrownBy(() -> RmiDoor.openFree(null, remote(), () -> {
                tried[0]++;
                return taken.getLocalPort();
            })).hasMessageContaining("in use?");
            assertThat(tried[0]).isEqualTo(5);
        }
    }
}
