package org.ripv.server.permit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

class QuotaLinesTest {
    @Test
    void firstMatchingQuotaLineDecidesElseTheDefault() {
        PermitFile p = PermitFile.parse(Path.of("p"), List.of(
                "user sam pbkdf2-sha256$1000$AAAA$AAAA observers",
                "user olga pbkdf2-sha256$1000$AAAA$AAAA observers",
                "user otto pbkdf2-sha256$1000$AAAA$AAAA operators",
                "quota sam 64K",
                "quota @observers 100M"));
        assertThat(p.quota(p.user("sam").orElseThrow())).isEqualTo(64 * 1024);
        assertThat(p.quota(p.user("olga").orElseThrow())).isEqualTo(100L << 20);
        assertThat(p.quota(p.user("otto").orElseThrow())).isEqualTo(PermitFile.DEFAULT_QUOTA);
        assertThatThrownBy(() -> PermitFile.parse(Path.of("p"), List.of("quota sam lots")))
                .hasMessageContaining("p:1").hasMessageContaining("'lots'");
        assertThatThrownBy(() -> PermitFile.parse(Path.of("p"), List.of("quota sam")))
                .hasMessageContaining("quota WHO BYTES");
    }

    @Test
    void theTemplateParsesAndGivesObserversAQuota() {
        PermitFile p = PermitFile.parse(Path.of("p"), List.of((PermitFile.TEMPLATE
                + "\nuser olga pbkdf2-sha256$1000$AAAA$AAAA observers").split("\n")));
        assertThat(p.quota(p.user("olga").orElseThrow())).isEqualTo(100L << 20);
        PermitFile.User olga = p.user("olga").orElseThrow();
        assertThat(p.decide(olga, "RIPVServer", "", "?replace mission.bin").allowed()).isFalse();
        assertThat(p.decide(olga, "RIPVServer", "", "?delete mission.bin").allowed()).isFalse();
        assertThat(p.decide(olga, "RIPVServer", "", "?upload mission.bin 0 10 keep").allowed()).isTrue();
    }
}
