package org.ripv.server.services;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BinaryOperator;

/**
 * The services registered now, by full name ({@code <DatabaseServer>::<host>}): the thesis's
 * ServiceReferences vector. Admission writes it, liveness checks remove from it, routing and the
 * {@code ?} commands read it; nobody else holds the table.
 */
public final class ServiceRegistry {
    private final Map<String, ServiceReference> services = new ConcurrentHashMap<>();

    /** The service of that full name, if it is registered. */
    public Optional<ServiceReference> find(String fullName) {
        return Optional.ofNullable(services.get(fullName));
    }

    /** The service a session token was handed to (every call but {@code register} carries one). */
    public Optional<ServiceReference> byToken(String token) {
        return services.values().stream().filter(r -> r.token().equals(token)).findFirst();
    }

    /** Every registered service, by name. */
    public List<ServiceReference> all() {
        return services.values().stream().sorted(Comparator.comparing(r -> r.descriptor().name())).toList();
    }

    public int size() {
        return services.size();
    }

    /**
     * Lists {@code ref} under its name; where one is listed already, {@code choose(old, ref)} says which stays.
     *
     * @return the reference in force afterwards, and the one it replaced (or null)
     */
    public Replacement put(ServiceReference ref, BinaryOperator<ServiceReference> choose) {
        ServiceReference[] replaced = new ServiceReference[1];
        ServiceReference now = services.compute(ref.descriptor().name(), (name, old) -> {
            ServiceReference kept = old == null ? ref : choose.apply(old, ref);
            replaced[0] = kept == ref ? old : null;
            return kept;
        });
        return new Replacement(now, replaced[0]);
    }

    /** The reference in force after {@link #put}, and the one it replaced (or null). */
    public record Replacement(ServiceReference now, ServiceReference replaced) {}

    /** Removes this very reference (not a newer registration of the same name); true when it was listed. */
    public boolean remove(ServiceReference ref) {
        return services.remove(ref.descriptor().name(), ref);
    }

    boolean isListed(String name) {
        return services.containsKey(name);
    }

    /** The server stops: every sender thread ends. */
    public void closeAll() {
        services.values().forEach(ServiceReference::close);
        services.clear();
    }
}
