package org.ripv.wire;

import java.io.ObjectInputFilter;
import java.lang.reflect.Proxy;
import java.rmi.Remote;
import java.util.Set;

/**
 * The allowlist for every object stream RIPV reads, on the client socket and on RMI: RIPV's own
 * message classes, the few JDK types they carry (a chart's {@code double[]} among them), and (on RMI) remote stubs of RIPV's interface.
 * Anything else, and anything deeper, bigger or with more references than the limits, is
 * rejected before it is instantiated.
 *
 * @param maxBytes         bytes one stream may hold
 * @param maxDepth         how deep objects may nest
 * @param maxRefs          references one stream may make
 * @param maxArray         the longest array
 * @param allowRemoteStubs true on RMI: stubs of RIPV's remote interface may come
 * @param allowRmiRuntime  true in a process that calls other RIPV processes: RMI's own leases and exceptions may come
 */
public record WireFilter(long maxBytes, long maxDepth, long maxRefs, long maxArray, boolean allowRemoteStubs,
                         boolean allowRmiRuntime) implements ObjectInputFilter {
    private static final String MESSAGES = "org.ripv.messages";
    private static final Set<String> JDK = Set.of(
            "java.lang.String", "java.lang.Enum", "java.lang.Number", "java.lang.Long", "java.lang.Integer",
            "java.lang.Double", "java.lang.Boolean",
            "java.util.ArrayList", "java.util.CollSer", "java.util.ImmutableCollections$ListN",
            "java.util.ImmutableCollections$List12",
            "java.util.Collections$UnmodifiableRandomAccessList", "java.util.Collections$UnmodifiableList",
            "java.util.Collections$UnmodifiableCollection",
            "[B", "[D", "[Ljava.lang.String;", "[Ljava.lang.Object;");
    private static final Set<String> RMI = Set.of(
            "java.lang.reflect.Proxy", "java.rmi.server.RemoteObjectInvocationHandler",
            "java.rmi.server.RemoteObject", "java.rmi.server.RemoteStub", "java.rmi.Remote");
    private static final String REMOTE_INTERFACE = "org.ripv.rmi.GenericRMIInterface";
    /** Travels inside every RIPV stub: the deadlines its caller connects and reads with. */
    private static final String SOCKET_FACTORY = "org.ripv.rmi.DeadlineSocketFactory";

    /** What RMI itself reads back in a process that calls other RIPV processes: DGC leases and exceptions. */
    private static final Set<String> RMI_RUNTIME = Set.of(
            "java.rmi.dgc.Lease", "java.rmi.dgc.VMID", "java.rmi.server.UID", "java.rmi.server.ObjID",
            "java.lang.StackTraceElement", "[Ljava.lang.StackTraceElement;", "java.util.Collections$EmptyList");

    /** The filter for one socket frame of at most {@code maxFrameBytes}. */
    public static WireFilter forFrames(int maxFrameBytes) {
        return new WireFilter(maxFrameBytes, 16, 2_000_000, maxFrameBytes, false, false);
    }

    /** The filter for RMI calls carrying messages of at most {@code maxBytes}. */
    public static WireFilter forRmi(long maxBytes) {
        return new WireFilter(maxBytes, 24, 2_000_000, maxBytes, true, false);
    }

    /**
     * The filter for a whole RIPV server or service process ({@link ObjectInputFilter.Config}):
     * what {@link #forRmi} accepts, plus what RMI's own machinery reads back from the processes
     * this one calls — distributed-GC leases and exceptions from the {@code java.*} packages.
     * With it, return values of RMI calls are filtered too, not only arguments.
     */
    public static WireFilter forProcess(long maxBytes) {
        return new WireFilter(maxBytes, 24, 2_000_000, maxBytes, true, true);
    }

    @Override
    public Status checkInput(FilterInfo info) {
        if (info.depth() > maxDepth || info.references() > maxRefs || info.streamBytes() > maxBytes
                || info.arrayLength() > maxArray) {
            return Status.REJECTED;
        }
        Class<?> c = info.serialClass();
        if (c == null) {
            return Status.UNDECIDED;
        }
        return allowed(c) ? Status.ALLOWED : Status.REJECTED;
    }

    private boolean allowed(Class<?> c) {
        // In a whole process, an embedded database reads its own stored descriptors back (Derby's
        // boolean[] when the DatabaseServer creates the Slocum tables): arrays of primitives are data
        // only, their length bounded by maxArray.
        if (allowRmiRuntime && c.isArray() && c.getComponentType().isPrimitive()) {
            return true;
        }
        while (c.isArray()) {
            if (c == byte[].class || c == double[].class || c == String[].class || c == Object[].class
                    || allowRmiRuntime && c == StackTraceElement[].class) {
                return true;
            }
            c = c.getComponentType();
        }
        String name = c.getName();
        if (c.getPackageName().equals(MESSAGES) || JDK.contains(name)) {
            return true;
        }
        if (!allowRemoteStubs) {
            return false;
        }
        if (RMI.contains(name) || name.equals(REMOTE_INTERFACE) || name.equals(SOCKET_FACTORY)) {
            return true;
        }
        if (allowRmiRuntime && (RMI_RUNTIME.contains(name)
                || Throwable.class.isAssignableFrom(c) && name.startsWith("java."))) {
            return true;
        }
        if (Proxy.isProxyClass(c)) {
            for (Class<?> i : c.getInterfaces()) {
                if (!i.getName().equals(REMOTE_INTERFACE) && i != Remote.class) {
                    return false;
                }
            }
            return true;
        }
        return false;
    }
}
