package org.ripv.post;

import org.ripv.messages.Message;

/** Key handling for the assistants, which live in another package. Not for service authors. */
public final class MailBoxes {
    private MailBoxes() {}

    public static void takeKey(MailBox<?, ?> box, Message request) {
        box.key().take(request);
    }

    public static void giveBackKey(MailBox<?, ?> box) {
        box.key().giveBack();
    }
}
