package org.ripv.slocum;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The one rule for what a Slocum file is, by name and by its first bytes. */
class SlocumFilesTest {
    static byte[] b(String s) {
        return s.getBytes(StandardCharsets.ISO_8859_1);
    }

    @Test
    void dbaTextByItsLabelLine() {
        assertThat(SlocumFiles.isDba(b(SlocumFiles.DBA_LABEL + "\nencoding_ver: 2\n"))).isTrue();
        assertThat(SlocumFiles.isDba(b(SlocumFiles.DBA_LABEL + "\r\n"))).isTrue();
        assertThat(SlocumFiles.isDba(b(SlocumFiles.DBA_LABEL + "X\n"))).isFalse();
        assertThat(SlocumFiles.isDba(b(SlocumFiles.DBA_LABEL))).as("nothing after the label").isFalse();
        assertThat(SlocumFiles.isDba(b("MISSION1.LOG"))).isFalse();
    }

    @Test
    void binaryFilesByLabelOrName() {
        assertThat(SlocumFiles.hasBinaryLabel(b("dbd_label:    DBD(dinkum_binary_data)file\nencoding_ver: 5\n"))).isTrue();
        assertThat(SlocumFiles.hasBinaryLabel(b("dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\n"))).isFalse();
        assertThat(SlocumFiles.hasBinaryLabel(b("dbd_label:\nDBD(dinkum_binary_data)file"))).as("second line").isFalse();
        assertThat(SlocumFiles.isBinaryName("01220000.DBD")).isTrue();
        assertThat(SlocumFiles.isBinaryName("01220000.scd")).isTrue();
        assertThat(SlocumFiles.isBinaryName("01220000.mrg")).isFalse();
        assertThat(SlocumFiles.isCompressedName("TTY1/01220000.DCD")).isTrue();
        assertThat(SlocumFiles.isCompressedName("01220000.dbd")).isFalse();
        assertThat(SlocumFiles.isCacheName("TTY1/6B016A2E.CAC")).isTrue();
        assertThat(SlocumFiles.isCacheName("6b016a2.cac")).isFalse();
    }

    @Test
    void theGliderIsNamedInTheHeader() {
        assertThat(SlocumFiles.vehicle(b("dbd_label: x\nfilename: cp_388-2016-012-0-0\n"))).isEqualTo("cp_388");
        assertThat(SlocumFiles.vehicle(b("dbd_label: x\nfull_filename: ru29\n"))).isEqualTo("ru29");
        assertThat(SlocumFiles.vehicle(b("no header"))).isNull();
    }
}
