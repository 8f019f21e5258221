package org.ripv.rmi;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.rmi.RemoteException;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.example.library.LibraryStream;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;

/**
 * Runs in a JVM of its own (the filter factory is once per JVM, and only before the first object
 * stream): installs RIPV's filters as a launcher does and prints one line per finding.
 */
public final class RmiStreamFiltersProbe {
    private RmiStreamFiltersProbe() {}

    static byte[] bytes(Object o) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        return b.toByteArray();
    }

    static String outcome(java.util.concurrent.Callable<?> c) {
        try {
            return "read " + c.call().getClass().getSimpleName();
        } catch (Exception e) {
            Throwable t = e;
            while (t.getCause() != null && !(t instanceof InvalidClassException)) {
                t = t.getCause();
            }
            return "refused " + t.getClass().getSimpleName();
        }
    }

    /** Answers with a hostile payload in a List<MailboxStatus>, and remembers what it was sent. */
    static final class Hostile extends DeadlineSocketFactoryTest.Probe {
        final AtomicReference<Object> received = new AtomicReference<>();

        @Override
        @SuppressWarnings({"unchecked", "rawtypes"})
        public List<MailboxStatus> mailboxes(String t) {
            return (List) List.of(new HashMap<>(Map.of("gadget", 1)));
        }

        @Override
        public void serviceReplies(String t, List<OutgoingServiceMessage> r) {
            received.set(r);
        }
    }

    public static void main(String[] args) throws Exception {
        System.out.println("installed " + RmiSupport.filterProcess() + " again " + RmiSupport.filterProcess());
        System.out.println("library boolean[] " + outcome(() -> LibraryStream.read(bytes(new boolean[] {true}))));
        System.out.println("library HashMap " + outcome(() -> LibraryStream.read(bytes(new HashMap<>(Map.of("a", 1))))));
        System.out.println("ripv HashMap " + outcome(() -> {
            try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes(new HashMap<>(Map.of("a", 1)))))) {
                return in.readObject();
            }
        }));
        System.out.println("ripv boolean[] " + outcome(() -> {
            try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes(new boolean[] {true})))) {
                return in.readObject();
            }
        }));
        Hostile obj = new Hostile();
        GenericRMIInterface stub = RmiSupport.export(obj, 0);
        try {
            System.out.println("rmi heartbeat " + stub.heartbeat("x"));
            System.out.println("rmi hostile reply " + outcome(() -> stub.mailboxes("x")));
            @SuppressWarnings({"unchecked", "rawtypes"})
            List<OutgoingServiceMessage> gadget = (List) List.of(new HashMap<>(Map.of("gadget", 1)));
            System.out.println("rmi hostile argument " + outcome(() -> {
                stub.serviceReplies("x", gadget);
                return obj.received.get() == null ? "nothing" : obj.received.get();
            }) + " delivered " + (obj.received.get() != null));
        } catch (RemoteException e) {
            System.out.println("rmi failed " + e);
        } finally {
            RmiSupport.unexport(obj);
        }
    }
}
