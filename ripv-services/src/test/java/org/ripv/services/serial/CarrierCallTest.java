package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;

/**
 * Carrier (DCD) as a call's start and end. No device on this machine raises DCD (a pty reports it
 * low), so the link here is an in-memory one whose carrier the test sets.
 */
class CarrierCallTest {
    @TempDir
    Path tmp;

    /** A serial link in memory: what the vehicle "prints" is offered by the test; DCD is a flag. */
    static final class ModemLink implements Link {
        final LinkedBlockingQueue<byte[]> incoming = new LinkedBlockingQueue<>();
        final AtomicBoolean dcd = new AtomicBoolean();
        volatile boolean closed;

        @Override
        public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
            if (closed) {
                throw new java.io.EOFException("closed");
            }
            try {
                byte[] b = incoming.poll(timeoutMillis, TimeUnit.MILLISECONDS);
                if (b == null) {
                    return 0;
                }
                System.arraycopy(b, 0, buffer, offset, b.length); // the test offers small chunks
                return b.length;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new java.io.InterruptedIOException();
            }
        }

        @Override
        public void write(byte[] buffer, int offset, int len) {
        }

        @Override
        public String describe() {
            return "/dev/ttyModem at 9600 8N1";
        }

        @Override
        public boolean hasCarrierLine() {
            return true;
        }

        @Override
        public boolean carrier() {
            return dcd.get();
        }

        @Override
        public void close() {
            closed = true;
        }

        void print(String s) {
            incoming.add(s.getBytes(StandardCharsets.US_ASCII));
        }
    }

    @Test
    void carrierRisingIsSurfacedAndFallingIsDived() throws Exception {
        ModemLink modem = new ModemLink();
        VehicleLink link = new VehicleLink(SimulatorOverTcpTest.settings("/dev/ttyModem").withCarrier(CarrierMode.REQUIRE),
                CallSettings.defaults().withName("ru29"));
        SerialPortServer serial = new SerialPortServer("testhost", List.of(link), null, false, tmp, s -> modem);
        ServiceProbe probe = new ServiceProbe(serial);
        serial.start();
        try {
            Eventually.await("no carrier", Duration.ofSeconds(5), () -> probe.status("ru29").detail().contains("DCD low"));
            modem.print("noise before the call\r\n");
            modem.dcd.set(true);
            modem.print("GPS Location:  4137.994 N -7032.188 E measured 26.0 secs ago\r\n");
            Eventually.await("SURFACED", Duration.ofSeconds(10), () -> !probe.events("ru29").isEmpty());
            ConsoleEntry surfaced = probe.events("ru29").get(0);
            assertThat(surfaced.event()).isEqualTo(VehicleEvent.SURFACED);
            assertThat(surfaced.text()).contains("carrier rose");
            assertThat(surfaced.lat()).isNotNull();
            assertThat(probe.status("ru29").available()).isTrue();
            modem.dcd.set(false);
            Eventually.await("DIVED", Duration.ofSeconds(10), () -> probe.events("ru29").size() == 2);
            assertThat(probe.events("ru29").get(1).event()).isEqualTo(VehicleEvent.DIVED);
            assertThat(probe.events("ru29").get(1).text()).contains("carrier fell");
            assertThat(probe.status("ru29").available()).isFalse();
            assertThat(probe.status("ru29").detail()).contains("dived at");
        } finally {
            serial.stop();
        }
    }
}
