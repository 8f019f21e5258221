package org.ripv.server.security;

import java.rmi.NotBoundException;
import java.rmi.Remote;
import java.rmi.RemoteException;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.RMIClientSocketFactory;
import java.rmi.server.RMIServerSocketFactory;
import org.ripv.rmi.GenericRMIInterface;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's RMI registry, which only the server binds in. The JDK's registry lets any process
 * on the same host bind, rebind and unbind; here every remote {@code bind} and {@code rebind} is
 * refused by the registry's serial filter (its arguments are never deserialized: the server binds
 * in-process, without serialization), and a remote {@code unbind} — which carries only a name and
 * so escapes any filter — is undone at the next check, within the service-check interval. Even
 * in that window an impostor learns nothing: services register by challenge–response.
 */
public final class RegistryGuard {
    private static final Logger log = LoggerFactory.getLogger(RegistryGuard.class);
    /** The JDK's filter for registry arguments; read once, when the first registry of the JVM is made. */
    static final String FILTER_PROPERTY = "sun.rmi.registry.registryFilter";

    static {
        install();
    }

    private final Registry registry;
    private final Remote stub;

    private RegistryGuard(Registry registry, Remote stub) {
        this.registry = registry;
        this.stub = stub;
    }

    /** Sets the filter that refuses remote binds, unless the operator set one. Call before any registry exists. */
    public static synchronized void install() {
        String now = System.getProperty(FILTER_PROPERTY);
        if (now == null) {
            System.setProperty(FILTER_PROPERTY, "!*");
        } else if (!now.contains("!*")) {
            log.warn("{}={} was set by hand: remote binds in the registry may be allowed", FILTER_PROPERTY, now);
        }
    }

    /** Creates the registry (remote binds refused). */
    public static Registry create(int port, RMIClientSocketFactory callSockets, RMIServerSocketFactory sockets)
            throws RemoteException {
        install();
        return LocateRegistry.createRegistry(port, callSockets, sockets);
    }

    /** Binds the server's stub (in-process) and returns a guard that keeps it bound. */
    public static RegistryGuard bind(Registry registry, Remote stub) throws RemoteException {
        registry.rebind(GenericRMIInterface.BINDING, stub);
        return new RegistryGuard(registry, stub);
    }

    /** Binds the stub again if someone unbound it (called on the service-check timer). */
    public void check() {
        try {
            Remote bound = registry.lookup(GenericRMIInterface.BINDING);
            if (bound == stub || stub.equals(bound)) {
                return;
            }
            Audit.log(true, "registry-repaired", "name", GenericRMIInterface.BINDING, "found", "another-object");
        } catch (NotBoundException e) {
            Audit.log(true, "registry-repaired", "name", GenericRMIInterface.BINDING, "found", "nothing");
        } catch (RemoteException e) {
            log.debug("registry check: {}", e.toString());
            return;
        }
        try {
            registry.rebind(GenericRMIInterface.BINDING, stub);
            log.warn("someone unbound {} from the RMI registry; bound the server again", GenericRMIInterface.BINDING);
        } catch (RemoteException e) {
            log.warn("could not bind {} again: {}", GenericRMIInterface.BINDING, e.toString());
        }
    }
}
