package org.ripv.server.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.ServiceName;

/**
 * The pages take a URL's {@code ?m=} only when it is one MailBox address by the server's own grammar
 * (issue 33 item 1): address.js must say exactly what {@link MailboxAddress} and {@link ServiceName} say.
 */
class AddressGrammarTest {
    @Test
    void thePagesAddressGrammarIsTheServers() throws Exception {
        String js;
        try (InputStream in = getClass().getResourceAsStream("/org/ripv/server/web/static/address.js")) {
            assertThat(in).as("address.js is served").isNotNull();
            js = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        assertThat(constant(js, "SERVICE")).isEqualTo(ServiceName.SERVICE);
        assertThat(constant(js, "HOST")).isEqualTo(ServiceName.HOST);
        assertThat(constant(js, "HANDLE")).isEqualTo(MailboxAddress.HANDLE);
    }

    /** The text of {@code export const NAME = '…';}, with the JS string's {@code \\} read as one backslash. */
    private static String constant(String js, String name) {
        Matcher m = Pattern.compile("export const " + name + " = '([^']*)';").matcher(js);
        assertThat(m.find()).as(name + " in address.js").isTrue();
        return m.group(1).replace("\\\\", "\\");
    }
}
