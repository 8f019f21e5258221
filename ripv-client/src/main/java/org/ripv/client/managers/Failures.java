package org.ripv.client.managers;

import java.net.ConnectException;
import java.net.UnknownHostException;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;

/** Turns a failure into the short phrase the operator reads in the status bar or a COM panel. */
final class Failures {
    private Failures() {}

    static String describe(Throwable e) {
        Throwable t = e;
        while ((t instanceof CompletionException || t instanceof ExecutionException) && t.getCause() != null) {
            t = t.getCause();
        }
        String m = t.getMessage();
        if (t instanceof ConnectException) {
            return "connection refused" + (m == null ? "" : " (" + m + ")");
        }
        if (t instanceof UnknownHostException) {
            return "unknown host " + m;
        }
        return m == null || m.isBlank() ? t.getClass().getSimpleName() : m;
    }
}
