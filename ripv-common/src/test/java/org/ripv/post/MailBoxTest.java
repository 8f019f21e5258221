package org.ripv.post;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;

class MailBoxTest {
    static IncomingServerMessage msg(String body, Priority p) {
        return new IncomingServerMessage(Header.request(0, "box", body, p));
    }

    @Test
    void takesTheOldestOfTheHighestNonEmptyPriorityFirst() throws Exception {
        MailBox<IncomingServerMessage, OutgoingServerMessage> box = new MailBox<>("box", 100);
        box.deliver(msg("n1", Priority.NORMAL));
        box.deliver(msg("p1", Priority.PRIORITY));
        box.deliver(msg("n2", Priority.NORMAL));
        box.deliver(msg("u1", Priority.URGENT));
        box.deliver(msg("p2", Priority.PRIORITY));
        box.deliver(msg("u2", Priority.URGENT));
        List<String> order = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            order.add(box.takeNext().header().body());
        }
        assertThat(order).containsExactly("u1", "u2", "p1", "p2", "n1", "n2");
        assertThat(box.pollNext(10, TimeUnit.MILLISECONDS)).isNull();
    }

    @Test
    void refusesBeyondItsCapacity() {
        MailBox<IncomingServerMessage, OutgoingServerMessage> box = new MailBox<>("box", 2);
        assertThat(box.deliver(msg("a", Priority.NORMAL))).isTrue();
        assertThat(box.deliver(msg("b", Priority.URGENT))).isTrue();
        assertThat(box.deliver(msg("c", Priority.URGENT))).isFalse();
        assertThat(box.waiting()).isEqualTo(2);
        assertThat(box.waiting(Priority.URGENT)).isEqualTo(1);
    }

    @Test
    void aWaitingTakerWakesWhenMailArrives() throws Exception {
        MailBox<IncomingServerMessage, OutgoingServerMessage> box = new MailBox<>("box", 10);
        Thread t = new Thread(() -> {
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                return;
            }
            box.deliver(msg("late", Priority.NORMAL));
        });
        t.start();
        assertThat(box.pollNext(5, TimeUnit.SECONDS).header().body()).isEqualTo("late");
    }

    @Test
    void theKeyIsHeldOnlyWhileACommandRuns() {
        MailBox<IncomingServerMessage, OutgoingServerMessage> box = new MailBox<>("box", 10);
        assertThat(box.key().isHeld()).isFalse();
        MailBoxes.takeKey(box, msg("dir", Priority.NORMAL));
        assertThat(box.key().isHeld()).isTrue();
        assertThat(box.key().holder().orElseThrow().command()).isEqualTo("dir");
        MailBoxes.giveBackKey(box);
        assertThat(box.key().isHeld()).isFalse();
    }
}
