package org.ripv.rmi;

import java.io.ObjectInputFilter;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.rmi.NoSuchObjectException;
import java.rmi.RemoteException;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.ExportException;
import java.rmi.server.RMIServerSocketFactory;
import java.rmi.server.UnicastRemoteObject;
import org.ripv.wire.WireFilter;

/** RMI settings every RIPV process uses, and exporting with the wire filter. */
public final class RmiSupport {
    /** The largest message RMI accepts (a whole file travels in one reply). */
    public static final long MAX_RMI_BYTES = 512L * 1024 * 1024;

    private RmiSupport() {}

    /**
     * Sets RMI's own timeouts before any RMI use (they bound RMI's handshake and a reply on a
     * pooled connection; the connect itself is bounded by {@link DeadlineSocketFactory}, with
     * which every RIPV object is exported).
     */
    public static void configure(long connectMillis, long responseMillis) {
        setIfAbsent("sun.rmi.transport.tcp.responseTimeout", Long.toString(responseMillis));
        setIfAbsent("sun.rmi.transport.connectionTimeout", Long.toString(connectMillis));
        setIfAbsent("sun.rmi.transport.proxy.connectTimeout", Long.toString(connectMillis));
        setIfAbsent("sun.rmi.transport.tcp.handshakeTimeout", Long.toString(connectMillis));
        // Distributed GC: notice dead peers in a minute rather than the default ten.
        setIfAbsent("java.rmi.dgc.leaseValue", "60000");
    }

    private static void setIfAbsent(String key, String value) {
        if (System.getProperty(key) == null) {
            System.setProperty(key, value);
        }
    }

    /**
     * Filters the object streams RMI and RIPV make in this process — above all the return values
     * of RMI calls to other RIPV processes — with {@link WireFilter#forProcess}, through a filter
     * factory ({@link RmiStreamFilters}) that leaves the streams of libraries such as Derby to
     * the JVM's own settings. For the launchers of servers and services, which own their JVM; a
     * library user keeps control of theirs. Idempotent; false when another factory was installed
     * first or an object stream was made before (the JVM then allows no factory).
     */
    public static synchronized boolean filterProcess() {
        if (ObjectInputFilter.Config.getSerialFilterFactory() instanceof RmiStreamFilters) {
            return true;
        }
        try {
            ObjectInputFilter.Config.setSerialFilterFactory(new RmiStreamFilters(
                    ObjectInputFilter.Config.getSerialFilterFactory(), WireFilter.forProcess(MAX_RMI_BYTES)));
            return true;
        } catch (IllegalStateException e) {
            return false;
        }
    }

    /**
     * The system property naming the address a service's RMI object listens on (the launchers'
     * {@code --bind}, which defaults to the address that reaches the server: loopback for a local
     * one). Unset, empty or {@code *}: every interface.
     */
    public static final String BIND_PROPERTY = "ripv.bind";

    /**
     * Exports an object on the given port (0: any) with the RIPV allowlist on its arguments,
     * listening on the {@link #BIND_PROPERTY} address when one is set, and with
     * {@link DeadlineSocketFactory} so that every caller connects and reads with deadlines.
     */
    public static GenericRMIInterface export(GenericRMIInterface object, int port) throws RemoteException {
        String bind = System.getProperty(BIND_PROPERTY, "").trim();
        if (bind.isEmpty() || bind.equals("*")) {
            return export(object, port, null);
        }
        InetAddress address;
        try {
            address = InetAddress.getByName(bind);
        } catch (UnknownHostException e) {
            throw new ExportException("cannot listen on '" + bind + "' (" + BIND_PROPERTY + "): unknown address", e);
        }
        return export(object, port, new BoundServerSocketFactory(address));
    }

    /** As {@link #export(GenericRMIInterface, int)}, listening through {@code sockets} (null: RMI's default). */
    public static GenericRMIInterface export(GenericRMIInterface object, int port, RMIServerSocketFactory sockets)
            throws RemoteException {
        return (GenericRMIInterface) UnicastRemoteObject.exportObject(object, port, DeadlineSocketFactory.fromSystem(), sockets,
                WireFilter.forRmi(MAX_RMI_BYTES));
    }

    /**
     * The RMI registry at host:port, reached through a {@link DeadlineSocketFactory}: a lookup
     * on an unreachable host fails within the connect deadline instead of minutes.
     */
    public static Registry registry(String host, int port) throws RemoteException {
        return LocateRegistry.getRegistry(host, port, DeadlineSocketFactory.fromSystem());
    }

    public static void unexport(GenericRMIInterface object) {
        try {
            UnicastRemoteObject.unexportObject(object, true);
        } catch (NoSuchObjectException ignored) {
            // already gone
        }
    }
}
