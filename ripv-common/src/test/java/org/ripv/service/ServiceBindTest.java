package org.ripv.service;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.Socket;
import java.util.Collections;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.rmi.RmiSupport;
import picocli.CommandLine;

/** A service launched for a server on this machine listens on loopback only, unless --bind says otherwise. */
class ServiceBindTest {
    private final String oldHostname = System.getProperty("java.rmi.server.hostname");

    @AfterEach
    void restore() {
        System.clearProperty(RmiSupport.BIND_PROPERTY);
        if (oldHostname == null) {
            System.clearProperty("java.rmi.server.hostname");
        } else {
            System.setProperty("java.rmi.server.hostname", oldHostname);
        }
    }

    private static ServiceLaunchOptions parse(String... args) {
        @CommandLine.Command
        class Holder {
            @CommandLine.Mixin
            ServiceLaunchOptions launch;
        }
        Holder h = new Holder();
        new CommandLine(h).parseArgs(args);
        return h.launch;
    }

    @Test
    void aLocalServerMeansLoopback() throws Exception {
        parse("--server", "localhost:1099").applyBind();
        assertThat(System.getProperty(RmiSupport.BIND_PROPERTY)).isEqualTo("127.0.0.1");
        assertThat(System.getProperty("java.rmi.server.hostname")).isEqualTo("127.0.0.1");
        assertThat(ServiceLaunchOptions.routeTo("127.0.0.1").isLoopbackAddress()).isTrue();
    }

    @Test
    void bindWidensIt() throws Exception {
        parse("--server", "localhost", "--bind", "*").applyBind();
        assertThat(System.getProperty(RmiSupport.BIND_PROPERTY)).isNull();
        parse("--server", "localhost", "--bind", "0.0.0.0").applyBind();
        assertThat(System.getProperty(RmiSupport.BIND_PROPERTY)).isEqualTo("0.0.0.0");
    }

    @Test
    void theExportedObjectIsNotReachableFromOtherInterfaces() throws Exception {
        System.setProperty(RmiSupport.BIND_PROPERTY, "127.0.0.1");
        GenericRMIInterface object = (GenericRMIInterface) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {GenericRMIInterface.class}, (p, m, a) -> null);
        GenericRMIInterface stub = RmiSupport.export(object, 0);
        try {
            Matcher m = Pattern.compile("endpoint:\\[([^:\\]]+):(\\d+)").matcher(stub.toString());
            assertThat(m.find()).as(stub.toString()).isTrue();
            int port = Integer.parseInt(m.group(2));
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 2000);
            }
            Optional<InetAddress> other = Collections.list(NetworkInterface.getNetworkInterfaces()).stream()
                    .flatMap(i -> Collections.list(i.getInetAddresses()).stream())
                    .filter(a -> !a.isLoopbackAddress() && a instanceof java.net.Inet4Address).findFirst();
            if (other.isPresent()) {
                try (Socket s = new Socket()) {
                    s.connect(new InetSocketAddress(other.get(), port), 2000);
                    throw new AssertionError("reachable on " + other.get() + ":" + port);
                } catch (java.net.ConnectException expected) {
                    // refused: it listens on loopback only
                }
            }
        } finally {
            RmiSupport.unexport(object);
        }
    }
}
