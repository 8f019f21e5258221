package org.ripv.naming;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class NamesTest {
    @Test
    void formatsAndParsesTheThesisExamples() {
        ServiceName db = ServiceName.parse("<DatabaseServer>::<deslab.mit.edu>");
        assertThat(db.service()).isEqualTo("DatabaseServer");
        assertThat(db.host()).isEqualTo("deslab.mit.edu");
        assertThat(db.toString()).isEqualTo("<DatabaseServer>::<deslab.mit.edu>");
        MailboxAddress com1 = MailboxAddress.parse("<SerialPortServer>::<imvros.mit.edu>COM1");
        assertThat(com1.service().service()).isEqualTo("SerialPortServer");
        assertThat(com1.handle()).isEqualTo("COM1");
        assertThat(com1.toString()).isEqualTo("<SerialPortServer>::<imvros.mit.edu>COM1");
        assertThat(db.mailbox("TTY1").toString()).isEqualTo("<DatabaseServer>::<deslab.mit.edu>TTY1");
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "DatabaseServer::deslab", "<DatabaseServer>::<>", "<Data base>::<h>", "<1abc>::<h>",
            "<X>::<h>::<i>", "<X>::<h"})
    void rejectsMalformedServiceNames(String bad) {
        assertThatThrownBy(() -> ServiceName.parse(bad)).isInstanceOf(MalformedNameException.class).hasMessageContaining("service");
    }

    @ParameterizedTest
    @ValueSource(strings = {"<X>::<h>", "<X>::<h>../etc", "<X>::<h>a b", "X::hCOM1", "<X>::<h>.hidden"})
    void rejectsMalformedMailboxAddresses(String bad) {
        assertThatThrownBy(() -> MailboxAddress.parse(bad)).isInstanceOf(MalformedNameException.class);
    }

    @Test
    void linkHandlesFollowTheSpec() {
        assertThat(Handles.forLink("/tmp/ttyV0")).isEqualTo("ttyV0");
        assertThat(Handles.forLink("/dev/ttyUSB0")).isEqualTo("ttyUSB0");
        assertThat(Handles.forLink("COM3")).isEqualTo("COM3");
        assertThat(Handles.forLink("tcp://glider.example.org:4001")).isEqualTo("tcp-glider.example.org-4001");
        assertThatThrownBy(() -> Handles.forLink("tcp://nohostport")).isInstanceOf(MalformedNameException.class);
        assertThat(Handles.platformDefault()).isIn("TTY1", "COM1");
    }
}
