package org.ripv.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.rmi.dgc.Lease;
import java.rmi.dgc.VMID;
import java.util.HashMap;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.MailboxStatus;

class WireFilterTest {
    static Object roundTrip(Object o, WireFilter filter) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(b.toByteArray()))) {
            in.setObjectInputFilter(filter);
            return in.readObject();
        }
    }

    @Test
    void theProcessFilterAdmitsWhatRmiReadsBackAndNothingElse() throws Exception {
        WireFilter process = WireFilter.forProcess(1 << 20);
        assertThat(roundTrip(new Lease(new VMID(), 60_000), process)).isInstanceOf(Lease.class);
        assertThat(roundTrip(new SecurityException("wrong service secret"), process)).isInstanceOf(SecurityException.class);
        assertThat(roundTrip(new java.rmi.RemoteException("gone", new IllegalStateException("x")), process))
                .isInstanceOf(java.rmi.RemoteException.class);
        assertThat(roundTrip(List.of(new MailboxStatus("<S>::<h>TTY1", true, "", false, "")), process)).isInstanceOf(List.class);
        assertThatThrownBy(() -> roundTrip(new HashMap<>(java.util.Map.of("a", 1)), process)).isInstanceOf(InvalidClassException.class);
        // Derby, embedded in the DatabaseServer, reads boolean[] back when it creates tables.
        assertThat(roundTrip(new boolean[] {true, false}, process)).isEqualTo(new boolean[] {true, false});
        assertThat(roundTrip(new int[] {1, 2}, process)).isEqualTo(new int[] {1, 2});
        assertThatThrownBy(() -> roundTrip(new boolean[] {true}, WireFilter.forFrames(1 << 20))).isInstanceOf(InvalidClassException.class);
        assertThatThrownBy(() -> roundTrip(new javax.swing.JLabel("gadget"), process)).isInstanceOf(InvalidClassException.class);
    }

    @Test
    void theFrameAndCallFiltersRefuseExceptionsAndLeases() {
        assertThatThrownBy(() -> roundTrip(new SecurityException("x"), WireFilter.forFrames(1 << 20)))
                .isInstanceOf(InvalidClassException.class);
        assertThatThrownBy(() -> roundTrip(new Lease(new VMID(), 1), WireFilter.forRmi(1 << 20)))
                .isInstanceOf(InvalidClassException.class);
    }
}
