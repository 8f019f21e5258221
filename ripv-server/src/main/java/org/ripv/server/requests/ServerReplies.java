package org.ripv.server.requests;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Result;

/**
 * How the server itself answers a request: every reply it makes names {@link #SERVICE} as the
 * last hop of its route, and permit rules name the server's own commands by the same word.
 */
public final class ServerReplies {
    /** The name rules and routes use for the server's own commands. */
    public static final String SERVICE = "RIPVServer";

    private ServerReplies() {}

    /** An ERROR reply from the server, with the command's FID. */
    public static OutgoingServerMessage error(IncomingServerMessage request, String fid, ErrorCode code, String text) {
        return request.reply(Footer.error(fid, code, text).via(SERVICE));
    }

    /** An OK reply from the server, with the command's FID and an optional typed result. */
    public static OutgoingServerMessage ok(IncomingServerMessage request, String fid, String text, Result result) {
        return request.reply(Footer.ok(fid, text, result).via(SERVICE));
    }
}
