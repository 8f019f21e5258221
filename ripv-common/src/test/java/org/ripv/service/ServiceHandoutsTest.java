package org.ripv.service;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.exceptions.ServiceException;
import org.ripv.handout.HandoutCollector;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileData;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.Priority;

/**
 * Only the server's own requests carry tickets: a user's upload named like a ticket list stays a
 * file; a bad ticket list from the server is refused with the text the server relays on; a
 * service that does not hand out files keeps nothing.
 */
class ServiceHandoutsTest {
    static final String DB = "<DatabaseServer>::<localhost>";

    static IncomingServiceMessage request(String clientId, Attachment a) {
        return new IncomingServiceMessage(new Header(1, new IdBadge(clientId, "alice"), List.of(), DB, DB + "TTY1",
                "ingest x", Priority.NORMAL, a));
    }

    @Test
    void ticketsCountOnlyFromTheServer() throws Exception {
        ServiceHandouts h = new ServiceHandouts(DB, () -> false);
        h.peersVia(s -> null);
        Attachment upload = new Attachment(HandoutCollector.ATTACHMENT, "just a user's text file\n".getBytes(StandardCharsets.UTF_8));
        IncomingServiceMessage fromUser = request("123456", upload);
        assertThat(h.collect(fromUser)).isSameAs(fromUser);
        assertThatThrownBy(() -> h.collect(request(IdBadge.SERVER.clientId(), upload)))
                .isInstanceOfSatisfying(ServiceException.class, e -> assertThat(e.code()).isEqualTo(ErrorCode.TRANSFER_FAILED))
                .hasMessageStartingWith(HandoutCollector.REFUSED);
    }

    @Test
    void aServiceThatDoesNotHandOutKeepsNothing() {
        ServiceHandouts h = new ServiceHandouts("<ClockService>::<localhost>", () -> false);
        h.keep(FileData.whole("a.txt", new byte[] {1, 2, 3}));
        assertThatThrownBy(() -> h.read("x", 0, 1, "token")).isInstanceOf(SecurityException.class).hasMessageContaining("holds no files");
    }
}
