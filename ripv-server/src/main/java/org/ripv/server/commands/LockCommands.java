package org.ripv.server.commands;

import java.time.Instant;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.VehicleEvent;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.workflow.Workflows;

/**
 * {@code ?lock MAILBOX [SECONDS]} and {@code ?unlock MAILBOX}: an operator keeps others from
 * commanding a MailBox for a while. A workflow's lock gives way to an operator's; watchers see
 * LOCK_TAKEN and LOCK_RELEASED.
 */
final class LockCommands {
    static final long MAX_LOCK_SECONDS = 3600;
    static final long DEFAULT_LOCK_SECONDS = 300;

    private final Map<String, OperatorLock> locks;
    private final ConsoleHub console;
    private final BiConsumer<String, OperatorLock> taken;
    private final Consumer<String> released;

    /**
     * @param taken    told of a lock taken or renewed (it ends by itself at its time)
     * @param released told of a MailBox unlocked (paused workflows look again)
     */
    LockCommands(Map<String, OperatorLock> locks, ConsoleHub console, BiConsumer<String, OperatorLock> taken,
                 Consumer<String> released) {
        this.locks = locks;
        this.console = console;
        this.taken = taken;
        this.released = released;
    }

    OutgoingServerMessage lock(Call c) {
        String user = c.userName();
        MailboxAddress address = MailboxAddress.parse(c.arg(1));
        long seconds = c.words().length >= 3 ? Call.number(c.words()[2], "SECONDS") : DEFAULT_LOCK_SECONDS;
        if (seconds < 1 || seconds > MAX_LOCK_SECONDS) {
            throw new IllegalArgumentException("a lock lasts 1 to " + MAX_LOCK_SECONDS + " seconds, not " + seconds);
        }
        OperatorLock mine = new OperatorLock(user, c.clientId(), System.currentTimeMillis() + seconds * 1000);
        OperatorLock now = locks.compute(address.toString(),
                (k, old) -> old == null || old.expired() || old.user().equals(user)
                        || Workflows.isWorkflowClient(old.clientId()) ? mine : old);
        if (now != mine) {
            return c.error(ErrorCode.MAILBOX_LOCKED,
                    address + " is locked by " + now.user() + " until " + Instant.ofEpochMilli(now.untilMillis()));
        }
        console.serverEvent(address.toString(), VehicleEvent.LOCK_TAKEN, user, "until " + Instant.ofEpochMilli(mine.untilMillis()));
        taken.accept(address.toString(), mine);
        return c.ok(address + " locked by " + user + " until " + Instant.ofEpochMilli(mine.untilMillis()), null);
    }

    OutgoingServerMessage unlock(Call c) {
        String user = c.userName();
        MailboxAddress address = MailboxAddress.parse(c.arg(1));
        OperatorLock l = locks.get(address.toString());
        if (l != null && !l.expired() && !l.user().equals(user)) {
            return c.error(ErrorCode.MAILBOX_LOCKED, address + " is locked by " + l.user() + ", not by you");
        }
        if (locks.remove(address.toString()) != null && l != null && !l.expired()) {
            console.serverEvent(address.toString(), VehicleEvent.LOCK_RELEASED, user, "");
        }
        released.accept(address.toString());
        return c.ok(address + " unlocked", null);
    }
}
