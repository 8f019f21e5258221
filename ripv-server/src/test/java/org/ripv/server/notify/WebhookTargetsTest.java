package org.ripv.server.notify;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.InetAddress;
import java.net.URI;
import org.junit.jupiter.api.Test;

class WebhookTargetsTest {
    private static InetAddress ip(String literal) throws Exception {
        return InetAddress.getByName(literal); // literals only: no DNS
    }

    @Test
    void onlyPublicAddressesPassByDefault() throws Exception {
        for (String s : new String[] {"127.0.0.1", "127.9.9.9", "::1", "0.0.0.0", "0.1.2.3", "::", "169.254.169.254",
                "fe80::1", "10.0.0.1", "172.31.255.255", "192.168.0.1", "100.64.0.1", "100.127.255.255", "fc00::1",
                "fdff::1", "224.0.0.1", "ff02::1", "198.18.0.1", "240.0.0.1", "255.255.255.255", "64:ff9b::a00:1",
                "::7f00:1", "2002:c0a8:101::1"}) {
            assertThat(WebhookTargets.restricted(ip(s))).as(s).isNotNull();
        }
        for (String s : new String[] {"8.8.8.8", "100.128.0.1", "172.32.0.1", "192.169.0.1", "2001:4860:4860::8888",
                "64:ff9b::808:808", "2002:808:808::1"}) {
            assertThat(WebhookTargets.restricted(ip(s))).as(s).isNull();
        }
    }

    @Test
    void allowedRangesOpenOnlyThemselves() {
        WebhookTargets t = WebhookTargets.parse("10.1.0.0/16, 127.0.0.1");
        t.check(URI.create("http://10.1.200.3/hook"));
        t.check(URI.create("http://127.0.0.1:8080/hook"));
        assertThatThrownBy(() -> t.check(URI.create("http://10.2.0.1/hook"))).hasMessageContaining("private address");
        assertThatThrownBy(() -> t.check(URI.create("http://127.0.0.2/hook"))).hasMessageContaining("loopback");
        WebhookTargets.parse("any").check(URI.create("http://169.254.169.254/"));
        assertThatThrownBy(() -> WebhookTargets.PUBLIC_ONLY.check(URI.create("http://[::1]/")))
                .hasMessageContaining("loopback");
    }

    @Test
    void badRangesAreRefusedClearly() {
        assertThatThrownBy(() -> WebhookTargets.parse("10.0.0.0/33")).hasMessageContaining("prefix length");
        assertThatThrownBy(() -> WebhookTargets.parse("example.org")).hasMessageContaining("CIDR");
        assertThatThrownBy(() -> WebhookTargets.parse("10.0.0.0/x")).hasMessageContaining("not a number");
        assertThat(WebhookTargets.parse("").toString()).isEqualTo("public addresses only");
    }
}
