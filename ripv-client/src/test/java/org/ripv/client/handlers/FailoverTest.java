package org.ripv.client.handlers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.net.ConnectException;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.failover.ServerList;

/** The order a server list is tried in (the real connections are ripv-it's FailoverTest and StandbyTest). */
class FailoverTest {
    @Test
    void aServerThatRefusedAtOnceIsTriedBeforeOneThatTimedOut() throws Exception {
        List<String> tried = new ArrayList<>();
        List<String> said = new ArrayList<>();
        Failover f = new Failover(ServerList.parse("a,b", 4444), said::add);
        boolean[] bServes = {false};
        Failover.Dialer dialer = (host, port) -> {
            tried.add(host);
            if (host.equals("a")) {
                sleep(60); // a cut-off host: the connect deadline runs out
                throw new SocketTimeoutException("connect timed out");
            }
            if (!bServes[0]) {
                throw new ConnectException("Connection refused"); // a standby: up, listening on nothing yet
            }
            return null;
        };
        assertThatThrownBy(() -> f.connect(dialer)).isInstanceOf(IOException.class)
                .hasMessageContaining("no server of a:4444,b:4444 answers").hasMessageContaining("a:4444 did not answer (connect timed out)");
        assertThat(tried).containsExactly("a", "b");
        bServes[0] = true;
        tried.clear();
        f.connect(dialer);
        assertThat(tried).as("the quick refusal first, the dead host not at all").containsExactly("b");
        assertThat(said).containsExactly("connected to b:4444 (server 2 of 2)");
        tried.clear();
        f.connect(dialer);
        assertThat(tried).as("the one that answered last, first").containsExactly("b");
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
