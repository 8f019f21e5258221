package org.ripv.server.remote;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.rmi.NoSuchObjectException;
import java.rmi.RemoteException;
import java.rmi.registry.Registry;
import java.rmi.server.ExportException;
import java.rmi.server.UnicastRemoteObject;
import org.ripv.probe.FreePorts;
import org.ripv.rmi.BoundServerSocketFactory;
import org.ripv.rmi.DeadlineSocketFactory;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.rmi.RmiSupport;
import org.ripv.server.security.RegistryGuard;
import org.ripv.wire.WireFilter;

/**
 * The server's RMI door: the registry it creates on the registry port (remote binds refused),
 * and {@link ServerRemote} exported on that same port, bound under
 * {@link GenericRMIInterface#BINDING}, with deadlines on the calls back and the RMI filter on
 * what services send. {@link #check} puts the binding back should anything have replaced it.
 */
public final class RmiDoor implements AutoCloseable {
    private final Registry registry;
    private final ServerRemote remote;
    private final RegistryGuard guard;
    private final int port;
    /** How many free ports a registry on port 0 tries before it gives up. */
    private static final int FREE_PORT_ATTEMPTS = 5;

    private RmiDoor(Registry registry, ServerRemote remote, RegistryGuard guard, int port) {
        this.registry = registry;
        this.remote = remote;
        this.guard = guard;
        this.port = port;
    }

    /** Opens the registry on {@code port} (0: a free one) on the bind address (null: all) and exports {@code remote} there. */
    public static RmiDoor open(InetAddress bind, int port, ServerRemote remote) throws IOException {
        return port == 0 ? openFree(bind, remote, FreePorts::one) : openOn(bind, port, remote);
    }

    /** Where {@link #openFree} gets the ports it tries. */
    @FunctionalInterface
    interface PortSource {
        int next() throws IOException;
    }

    // RMI cannot tell which port a registry on port 0 took, so a free one is picked first; another
    // process may still take it before the registry binds it. Another free port then, a few times.
    static RmiDoor openFree(InetAddress bind, ServerRemote remote, PortSource ports) throws IOException {
        for (int attempt = 1; ; attempt++) {
            try {
                return openOn(bind, ports.next(), remote);
            } catch (IOException e) {
                // openOn wraps the registry's ExportException, which wraps the bind's failure
                boolean taken = e.getCause() instanceof ExportException x && x.getCause() instanceof BindException;
                if (attempt == FREE_PORT_ATTEMPTS || !taken) {
                    throw e;
                }
            }
        }
    }

    private static RmiDoor openOn(InetAddress bind, int registryPort, ServerRemote remote) throws IOException {
        BoundServerSocketFactory rmiSockets = new BoundServerSocketFactory(bind);
        // Services call back with deadlines: the factory travels inside the stub they get.
        DeadlineSocketFactory callSockets = DeadlineSocketFactory.fromSystem();
        Registry registry;
        try {
            registry = RegistryGuard.create(registryPort, callSockets, rmiSockets);
        } catch (RemoteException e) {
            throw new IOException("cannot open the RMI registry on port " + registryPort + " (in use?): " + e.getMessage(), e);
        }
        try {
            GenericRMIInterface stub = (GenericRMIInterface) UnicastRemoteObject.exportObject(remote,
                    registryPort, callSockets, rmiSockets, WireFilter.forRmi(RmiSupport.MAX_RMI_BYTES));
            return new RmiDoor(registry, remote, RegistryGuard.bind(registry, stub), registryPort);
        } catch (IOException | RuntimeException e) {
            new RmiDoor(registry, remote, null, registryPort).close();
            throw e;
        }
    }

    /** The registry port (useful with port 0). */
    public int port() {
        return port;
    }

    /** Binds the server's stub again if anything replaced it (each service check). */
    public void check() {
        if (guard != null) {
            guard.check();
        }
    }

    /** Unbinds, closes the registry and withdraws the server's remote object. */
    @Override
    public void close() {
        try {
            registry.unbind(GenericRMIInterface.BINDING);
        } catch (Exception ignored) {
            // not bound, or already gone
        }
        try {
            UnicastRemoteObject.unexportObject(registry, true);
        } catch (NoSuchObjectException ignored) {
            // not exported
        }
        RmiSupport.unexport(remote);
    }
}
