package org.ripv.server.vehicles;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class VehicleNamesTest {
    static final String SIM = "<SerialPortServer>::<localhost>sim01";
    static final String RU = "<SerialPortServer>::<shore>ru29";
    static final String TTY_A = "<SerialPortServer>::<localhost>ttyS0";
    static final String TTY_B = "<SerialPortServer>::<shore>ttyS0";
    static final List<String> KNOWN = List.of(SIM, RU, TTY_A, TTY_B, "<DataVisServer>::<localhost>vis", "not an address");

    @Test
    void aNameOrHandleOfOneMailBoxIsItsFullAddress() {
        assertThat(VehicleNames.resolve("sim01", KNOWN, List.of()).address()).isEqualTo(SIM);
        assertThat(VehicleNames.resolve("ru29", KNOWN, List.of()).address()).isEqualTo(RU);
        assertThat(VehicleNames.resolve("vis", KNOWN, List.of()).address()).isEqualTo("<DataVisServer>::<localhost>vis");
    }

    @Test
    void caseIsForgivenOnlyWhenNoHandleMatchesExactly() {
        assertThat(VehicleNames.resolve("SIM01", KNOWN, List.of()).address()).isEqualTo(SIM);
        List<String> both = List.of(SIM, "<SerialPortServer>::<shore>SIM01");
        assertThat(VehicleNames.resolve("sim01", both, List.of()).address()).isEqualTo(SIM);
        assertThat(VehicleNames.resolve("Sim01", both, List.of()).error()).contains("names 2 MailBoxes");
    }

    @Test
    void anAmbiguousNameListsTheCandidatesFullAddresses() {
        VehicleNames.Resolution r = VehicleNames.resolve("ttyS0", KNOWN, List.of());
        assertThat(r.resolved()).isFalse();
        assertThat(r.error()).isEqualTo("'ttyS0' names 2 MailBoxes: " + TTY_A + ", " + TTY_B
                + "; give the full address of the one you mean");
    }

    @Test
    void anUnknownNameSaysWhichNamesExistAndWhoDidNotAnswer() {
        VehicleNames.Resolution r = VehicleNames.resolve("sim02", KNOWN, List.of("<DatabaseServer>::<db>"));
        assertThat(r.resolved()).isFalse();
        assertThat(r.error()).isEqualTo("no vehicle or MailBox is called 'sim02'; the names are: ru29, sim01, ttyS0, vis"
                + " (not answering, so not asked: <DatabaseServer>::<db>); ?mailboxes lists the full addresses");
        assertThat(VehicleNames.resolve("sim01", List.of(), List.of()).error())
                .isEqualTo("no vehicle or MailBox is called 'sim01'; no service lists any MailBox now; ?mailboxes lists the full addresses");
    }

    @Test
    void aFullAddressIsTakenAsItIsAndAMalformedOneSaysTheForm() {
        assertThat(VehicleNames.resolve(" <SerialPortServer>::<elsewhere>x9".trim(), KNOWN, List.of()).address())
                .isEqualTo("<SerialPortServer>::<elsewhere>x9");
        assertThat(VehicleNames.resolve("<SerialPortServer>::sim01", KNOWN, List.of()).error())
                .contains("is not a mailbox address of the form <Service>::<host>HANDLE");
    }

    @Test
    void theMailBoxWordOfEachCommand() {
        assertThat(MailboxArgument.position("?history sim01 --last 5".split(" "))).isEqualTo(1);
        assertThat(MailboxArgument.position("?STATUS sim01".split(" "))).isEqualTo(1);
        for (String c : List.of("?lock", "?unlock", "?watch", "?unwatch", "?receipts", "?queue")) {
            assertThat(MailboxArgument.position((c + " sim01").split(" "))).as(c).isEqualTo(1);
        }
        assertThat(MailboxArgument.position("?queue add sim01 dive.wf".split(" "))).isEqualTo(2);
        assertThat(MailboxArgument.position("?queue remove sim01 3".split(" "))).isEqualTo(2);
        assertThat(MailboxArgument.position("?queue clear sim01".split(" "))).isEqualTo(2);
        assertThat(MailboxArgument.position("?queue add".split(" "))).isEqualTo(-1);
        assertThat(MailboxArgument.position("?history".split(" "))).isEqualTo(-1);
        assertThat(MailboxArgument.position("?notify add email a@b.c all sim*".split(" "))).isEqualTo(-1);
        assertThat(MailboxArgument.replaced("?queue add sim01 dive.wf".split(" "), 2, SIM)).isEqualTo("?queue add " + SIM + " dive.wf");
    }
}
