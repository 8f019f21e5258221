package org.ripv.messages;

import java.util.List;

/** The MailBoxes of the registered services ({@code ?mailboxes}), for the MAM tree. */
public record MailboxList(List<MailboxStatus> mailboxes) implements Result {
    public MailboxList {
        mailboxes = List.copyOf(mailboxes);
    }
}
