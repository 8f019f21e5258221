package org.ripv.handout;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.rmi.RemoteException;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Attachment;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;

/**
 * The rules of a handout (issue 34): a ticket the server signed with the holder's session token
 * reads its file once, in order, within its time; a forged, foreign, expired, replayed or
 * out-of-order one is refused, and so is a file let go. The collector checks every byte the holder
 * sends. (The holder is called in-process here; HandoutEndToEndTest calls it over RMI between launched jars.)
 */
class HandoutsTest {
    static final String SERIAL = "<SerialPortServer>::<glider-host>";
    static final String DB = "<DatabaseServer>::<db-host>";
    static final String TOKEN = "a1".repeat(32);

    final AtomicLong now = new AtomicLong(1_000_000);
    final Handouts held = new Handouts(1000, Duration.ofMinutes(15), now::get);

    static byte[] bytes(int n, int seed) {
        byte[] b = new byte[n];
        for (int i = 0; i < n; i++) {
            b[i] = (byte) (i * 31 + seed);
        }
        return b;
    }

    HandoutTicket ticket(byte[] data) {
        return HandoutTicket.sign(TOKEN, SERIAL, DB, data, now.get() + 60_000);
    }

    @Test
    void aSignedTicketReadsItsFileOnceInOrder() throws Exception {
        byte[] data = bytes(700, 1);
        held.hold(data);
        String t = ticket(data).text();
        byte[] a = held.read(t, 0, 300, SERIAL, TOKEN);
        byte[] b = held.read(t, 300, 300, SERIAL, TOKEN);
        byte[] c = held.read(t, 600, 300, SERIAL, TOKEN);
        assertThat(c).hasSize(100);
        byte[] all = new byte[700];
        System.arraycopy(a, 0, all, 0, 300);
        System.arraycopy(b, 0, all, 300, 300);
        System.arraycopy(c, 0, all, 600, 100);
        assertThat(all).isEqualTo(data);
        // replayed: from the start again, or past the end
        assertThatThrownBy(() -> held.read(t, 0, 300, SERIAL, TOKEN)).isInstanceOf(HandoutRefused.class).hasMessageContaining("used");
        assertThatThrownBy(() -> held.read(t, 700, 1, SERIAL, TOKEN)).isInstanceOf(HandoutRefused.class).hasMessageContaining("used");
    }

    @Test
    void aReadOutOfOrderOrNotFromTheStartIsRefused() throws Exception {
        byte[] data = bytes(500, 2);
        held.hold(data);
        String t = ticket(data).text();
        assertThatThrownBy(() -> held.read(t, 100, 100, SERIAL, TOKEN)).hasMessageContaining("used");
        held.read(t, 0, 100, SERIAL, TOKEN);
        assertThatThrownBy(() -> held.read(t, 200, 100, SERIAL, TOKEN)).hasMessageContaining("used");
        assertThatThrownBy(() -> held.read(t, 100, 0, SERIAL, TOKEN)).hasMessageContaining("chunks");
        assertThatThrownBy(() -> held.read(t, 100, Handouts.MAX_CHUNK + 1, SERIAL, TOKEN)).hasMessageContaining("chunks");
    }

    @Test
    void aForgedOrForeignTicketIsRefused() throws Exception {
        byte[] data = bytes(200, 3);
        held.hold(data);
        HandoutTicket good = ticket(data);
        // signed with another session's token: a forgery, or a ticket from before a re-registration
        String other = HandoutTicket.sign("b2".repeat(32), SERIAL, DB, data, now.get() + 60_000).text();
        assertThatThrownBy(() -> held.read(other, 0, 100, SERIAL, TOKEN)).hasMessageContaining("forged");
        // a field changed after signing: a longer life, another size
        String longer = new HandoutTicket(good.source(), good.destination(), good.sha256(), good.size(), good.expiresAt() + 1,
                good.nonce(), good.mac()).text();
        assertThatThrownBy(() -> held.read(longer, 0, 100, SERIAL, TOKEN)).hasMessageContaining("forged");
        // a holder that is not registered has no token: nothing verifies
        assertThatThrownBy(() -> held.read(good.text(), 0, 100, SERIAL, null)).hasMessageContaining("forged");
        // meant for another holder
        assertThatThrownBy(() -> held.read(good.text(), 0, 100, "<SerialPortServer>::<elsewhere>", TOKEN))
                .hasMessageContaining("names " + SERIAL);
        // not a ticket at all
        for (String junk : List.of("", "ripv-handout-1 x", "x".repeat(HandoutTicket.MAX_TEXT + 1),
                good.text().replace("ripv-handout-1", "ripv-handout-2"), good.text().replace(good.sha256(), "zz"))) {
            assertThatThrownBy(() -> held.read(junk, 0, 100, SERIAL, TOKEN)).isInstanceOf(HandoutRefused.class)
                    .hasMessageContaining("not a handout ticket");
        }
        assertThat(held.read(good.text(), 0, 200, SERIAL, TOKEN)).isEqualTo(data); // the good one still reads
    }

    @Test
    void anExpiredTicketAndAFileLetGoAreRefused() throws Exception {
        byte[] data = bytes(200, 4);
        held.hold(data);
        String t = ticket(data).text();
        now.addAndGet(60_001);
        assertThatThrownBy(() -> held.read(t, 0, 100, SERIAL, TOKEN)).hasMessageContaining("expired");
        // held 15 minutes only
        now.addAndGet(Duration.ofMinutes(16).toMillis());
        String later = HandoutTicket.sign(TOKEN, SERIAL, DB, data, now.get() + 60_000).text();
        assertThat(held.heldBytes()).isZero();
        assertThatThrownBy(() -> held.read(later, 0, 100, SERIAL, TOKEN)).hasMessageContaining("no longer holds");
    }

    @Test
    void theStoreIsBoundedAndLetsTheOldestGo() throws Exception {
        byte[] a = bytes(600, 5);
        byte[] b = bytes(600, 6);
        held.hold(a);
        held.hold(b); // 1,200 > 1,000: a goes
        held.hold(bytes(1001, 7)); // larger than the whole store: not kept at all
        assertThat(held.heldBytes()).isEqualTo(600);
        assertThatThrownBy(() -> held.read(ticket(a).text(), 0, 100, SERIAL, TOKEN)).hasMessageContaining("no longer holds");
        assertThat(held.read(ticket(b).text(), 0, 600, SERIAL, TOKEN)).isEqualTo(b);
    }

    /** A holder reached directly; {@code tamper} changes what it sends. */
    GenericRMIInterface holder(java.util.function.UnaryOperator<byte[]> tamper) {
        return new Holder() {
            @Override
            public byte[] handout(String ticket, long offset, int max) {
                try {
                    return tamper.apply(held.read(ticket, offset, max, SERIAL, TOKEN));
                } catch (HandoutRefused e) {
                    throw new SecurityException(e.getMessage());
                }
            }
        };
    }

    @Test
    void theCollectorReadsTheFilesAndChecksEveryByte() throws Exception {
        byte[] one = bytes(Handouts.MAX_CHUNK + 10, 8);
        Handouts big = new Handouts(4L << 20, Duration.ofMinutes(15), now::get);
        big.hold(one);
        byte[] two = "dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\n".getBytes(StandardCharsets.UTF_8);
        big.hold(two);
        Attachment tickets = HandoutCollector.attachment(List.of(
                new HandoutCollector.Entry("f/one.mrg", HandoutTicket.sign(TOKEN, SERIAL, DB, one, now.get() + 60_000)),
                new HandoutCollector.Entry("f/two.mrg", HandoutTicket.sign(TOKEN, SERIAL, DB, two, now.get() + 60_000))));
        assertThat(HandoutCollector.carriesTickets(tickets)).isTrue();
        GenericRMIInterface h = new Holder() {
            @Override
            public byte[] handout(String ticket, long offset, int max) {
                try {
                    return big.read(ticket, offset, max, SERIAL, TOKEN);
                } catch (HandoutRefused e) {
                    throw new SecurityException(e.getMessage());
                }
            }
        };
        Attachment got = HandoutCollector.collect(tickets, s -> s.equals(SERIAL) ? h : null, DB, 8L << 20);
        List<Attachment> files = got.files(10);
        assertThat(files).extracting(Attachment::name).containsExactly("f/one.mrg", "f/two.mrg");
        assertThat(files.get(0).data()).isEqualTo(one);
        assertThat(files.get(1).data()).isEqualTo(two);
        // the same tickets again: replayed
        assertThatThrownBy(() -> HandoutCollector.collect(tickets, s -> h, DB, 8L << 20))
                .isInstanceOf(HandoutRefused.class).hasMessageContaining("used");
    }

    @Test
    void theCollectorRefusesWhatItWasNotPromised() throws Exception {
        byte[] data = bytes(300, 9);
        held.hold(data);
        Attachment tickets = HandoutCollector.attachment(List.of(new HandoutCollector.Entry("f/a.mrg", ticket(data))));
        // meant for another DatabaseServer
        assertThatThrownBy(() -> HandoutCollector.collect(tickets, s -> holder(b -> b), "<DatabaseServer>::<other>", 1000))
                .hasMessageContaining("meant for " + DB);
        // more than the limit: refused before a byte is read
        assertThatThrownBy(() -> HandoutCollector.collect(tickets, s -> holder(b -> b), DB, 299)).hasMessageContaining("more than 299");
        // a holder out of reach
        assertThatThrownBy(() -> HandoutCollector.collect(tickets, s -> null, DB, 1000)).hasMessageContaining("cannot be reached");
        assertThatThrownBy(() -> HandoutCollector.collect(tickets, s -> {
            throw new RemoteException("Connection refused");
        }, DB, 1000)).hasMessageContaining("Connection refused");
        // a holder that sends other bytes, or more than asked
        byte[] data2 = bytes(300, 10);
        held.hold(data2);
        Attachment t2 = HandoutCollector.attachment(List.of(new HandoutCollector.Entry("f/b.mrg", ticket(data2))));
        assertThatThrownBy(() -> HandoutCollector.collect(t2, s -> holder(b -> {
            byte[] c = b.clone();
            c[0] ^= 1;
            return c;
        }), DB, 1000)).hasMessageContaining("SHA-256 differs");
        byte[] data3 = bytes(300, 11);
        held.hold(data3);
        Attachment t3 = HandoutCollector.attachment(List.of(new HandoutCollector.Entry("f/c.mrg", ticket(data3))));
        assertThatThrownBy(() -> HandoutCollector.collect(t3, s -> holder(b -> Arrays.copyOf(b, b.length + 1)), DB, 1000))
                .hasMessageContaining("301 bytes where 1 to 300 belonged");
        // a list that is not one
        assertThatThrownBy(() -> HandoutCollector.collect(new Attachment(HandoutCollector.ATTACHMENT, "no tab\n".getBytes()),
                s -> null, DB, 1000)).hasMessageContaining("without a file name");
        assertThatThrownBy(() -> HandoutCollector.collect(new Attachment(HandoutCollector.ATTACHMENT, new byte[0]),
                s -> null, DB, 1000)).hasMessageContaining("empty");
    }

    /** What a service answers; only {@code handout} matters here. */
    abstract static class Holder implements GenericRMIInterface {
        @Override
        public String challenge(String serviceNonce) {
            throw new UnsupportedOperationException();
        }

        @Override
        public String register(ServiceDescriptor descriptor, GenericRMIInterface service, String proof) {
            throw new UnsupportedOperationException();
        }

        @Override
        public void serviceReply(String token, OutgoingServiceMessage reply) {
            throw new UnsupportedOperationException();
        }

        @Override
        public void serviceReplies(String token, List<OutgoingServiceMessage> replies) {
            throw new UnsupportedOperationException();
        }

        @Override
        public void console(String token, List<ConsoleEntry> entries) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean heartbeat(String token) {
            return true;
        }

        @Override
        public void serviceRequest(String token, IncomingServiceMessage request) {
            throw new UnsupportedOperationException();
        }

        @Override
        public void serviceRequests(String token, List<IncomingServiceMessage> requests) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean withdraw(String token, String mailbox, String clientId, long messageId) {
            throw new UnsupportedOperationException();
        }

        @Override
        public List<MailboxStatus> mailboxes(String token) {
            throw new UnsupportedOperationException();
        }
    }
}
