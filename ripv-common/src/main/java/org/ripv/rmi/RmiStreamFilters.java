package org.ripv.rmi;

import java.io.ObjectInputFilter;
import java.util.Iterator;
import java.util.function.BinaryOperator;

/**
 * The process's deserialization filter factory: RIPV's allowlist for the object streams RMI and
 * RIPV make, every other stream left as the JVM would leave it.
 *
 * <p>A JVM-wide filter ({@link ObjectInputFilter.Config#setSerialFilter}) would also judge the
 * streams libraries make for themselves — Derby restores a {@code boolean[]} from its own object
 * streams while it creates tables — and refuse them. The factory instead looks at who is
 * constructing each stream: RMI's transport ({@code sun.rmi}, {@code java.rmi}) or RIPV's own
 * code gets {@link org.ripv.wire.WireFilter#forProcess}, so every return value and argument RIPV
 * receives over RMI is still allowlisted; a filter requested later for such a stream (RMI's
 * per-export filters, {@code WireFilter.forFrames}) replaces it, as without a factory.
 */
final class RmiStreamFilters implements BinaryOperator<ObjectInputFilter> {
    private static final StackWalker WALKER = StackWalker.getInstance();
    private static final String STREAM = "java.io.ObjectInputStream";

    private final BinaryOperator<ObjectInputFilter> previous;
    private final ObjectInputFilter rmi;

    RmiStreamFilters(BinaryOperator<ObjectInputFilter> previous, ObjectInputFilter rmi) {
        this.previous = previous;
        this.rmi = rmi;
    }

    @Override
    public ObjectInputFilter apply(ObjectInputFilter current, ObjectInputFilter requested) {
        if (current == rmi) {
            return requested != null ? requested : rmi;
        }
        if (current == null && isRipvOrRmi(creator())) {
            return rmi;
        }
        return previous.apply(current, requested);
    }

    /** True for the class names whose streams RIPV's allowlist judges. */
    static boolean isRipvOrRmi(String creator) {
        return creator != null && (creator.startsWith("sun.rmi.") || creator.startsWith("java.rmi.")
                || creator.startsWith("org.ripv."));
    }

    /**
     * The class constructing the stream this call is for (a subclass's constructor, such as RMI's
     * {@code MarshalInputStream}, counts as its maker), or null when the stream is not being
     * constructed but given a filter later.
     */
    private static String creator() {
        return WALKER.walk(frames -> {
            Iterator<StackWalker.StackFrame> it = frames.iterator();
            boolean inStream = false;
            boolean constructing = false;
            while (it.hasNext()) {
                StackWalker.StackFrame f = it.next();
                if (f.getClassName().equals(STREAM)) {
                    inStream = true;
                    constructing = f.getMethodName().equals("<init>");
                } else if (inStream) {
                    return constructing ? f.getClassName() : null;
                }
            }
            return null;
        });
    }
}
