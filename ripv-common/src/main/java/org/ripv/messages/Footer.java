package org.ripv.messages;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * The answering half of a {@link Message}.
 *
 * @param serviceId the SID of the service that produced the reply, or the FID of the server
 *                  command that did; clients dispatch on it (Appendix B)
 * @param status    PROGRESS for interim replies, then exactly one OK or ERROR
 * @param errorCode why it failed, {@link ErrorCode#NONE} unless status is ERROR
 * @param route     the parts of the system the message has passed through, in order
 * @param replyText text for the operator: a device's answer, a summary, or the error message
 * @param result    a typed result (listing, table, image, file), or null
 */
public record Footer(String serviceId, Status status, ErrorCode errorCode, List<String> route,
                     String replyText, Result result) implements Serializable {

    public Footer {
        Ids.require(serviceId);
        Objects.requireNonNull(status, "status");
        errorCode = errorCode == null ? ErrorCode.NONE : errorCode;
        route = route == null ? List.of() : List.copyOf(route);
        replyText = replyText == null ? "" : replyText;
        if (status == Status.ERROR && errorCode == ErrorCode.NONE) {
            errorCode = ErrorCode.INTERNAL;
        }
    }

    /** The footer of a request that has not been answered yet. */
    public static Footer unanswered() {
        return new Footer(Ids.FID_NONE, Status.OK, ErrorCode.NONE, List.of(), "", null);
    }

    public static Footer ok(String serviceId, String text, Result result) {
        return new Footer(serviceId, Status.OK, ErrorCode.NONE, List.of(), text, result);
    }

    public static Footer progress(String serviceId, String text, Result result) {
        return new Footer(serviceId, Status.PROGRESS, ErrorCode.NONE, List.of(), text, result);
    }

    public static Footer error(String serviceId, ErrorCode code, String text) {
        return new Footer(serviceId, Status.ERROR, code, List.of(), text, null);
    }

    /** This footer with one more hop on its route. */
    public Footer via(String hop) {
        List<String> r = new ArrayList<>(route);
        r.add(hop);
        return new Footer(serviceId, status, errorCode, r, replyText, result);
    }

    public Footer withResult(Result newResult) {
        return new Footer(serviceId, status, errorCode, route, replyText, newResult);
    }

    public Footer withText(String text) {
        return new Footer(serviceId, status, errorCode, route, text, result);
    }

    @Override
    public String toString() {
        return "Footer[" + serviceId + " " + status + (status == Status.ERROR ? " " + errorCode : "")
                + " '" + Header.abbreviate(replyText) + "'" + (result == null ? "" : " " + result.getClass().getSimpleName())
                + "]";
    }
}
