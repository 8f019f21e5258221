package org.ripv.failover;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class ServerListTest {
    @Test
    void hostsWithAndWithoutPortsInOrder() {
        ServerList l = ServerList.parse(" srv1 , //srv2:2099,[fd00::1]:4445,[fd00::2]", 1099);
        assertThat(l.servers()).containsExactly(new ServerList.Endpoint("srv1", 1099), new ServerList.Endpoint("srv2", 2099),
                new ServerList.Endpoint("fd00::1", 4445), new ServerList.Endpoint("fd00::2", 1099));
        assertThat(l.toString()).isEqualTo("srv1:1099,srv2:2099,[fd00::1]:4445,[fd00::2]:1099");
        assertThat(l.position(1)).isEqualTo(" (server 2 of 4)");
        assertThat(ServerList.parse("one", 4444).position(0)).isEmpty();
        assertThat(l.next(3)).isZero();
        assertThat(ServerList.parse("a,a:1099", 1099).size()).as("duplicates dropped").isEqualTo(1);
    }

    @Test
    void badListsSayWhichPartIsWrong() {
        assertThatThrownBy(() -> ServerList.parse("a,b:x", 1)).hasMessageContaining("'b:x': the port is not a number");
        assertThatThrownBy(() -> ServerList.parse("a,,b", 1)).hasMessageContaining("'': no host");
        assertThatThrownBy(() -> ServerList.parse("a:70000", 1)).hasMessageContaining("not 1 to 65535");
        assertThatThrownBy(() -> ServerList.parse("[::1", 1)).hasMessageContaining("unclosed");
        assertThatThrownBy(() -> ServerList.parse(" ", 1)).hasMessageContaining("no server given");
        assertThatThrownBy(() -> ServerList.parse("a,b,c,d,e,f,g,h,i", 1)).hasMessageContaining("at most 8");
    }
}
