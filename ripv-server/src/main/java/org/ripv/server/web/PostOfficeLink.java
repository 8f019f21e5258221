package org.ripv.server.web;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.util.function.Consumer;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One page's connection to the Post Office: the client's end of a connection the server adopted
 * (see {@link PostOfficeDoor}). Requests go out as frames; a reader thread hands every reply and
 * console push to the page. Closing it is the client disconnecting: the server forgets its
 * watches, pending requests and locks as for any client.
 */
final class PostOfficeLink implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(PostOfficeLink.class);

    private final Socket socket;
    private final FrameCodec codec;
    private final DataOutputStream out;
    private final DataInputStream in;
    private final Thread reader;
    private volatile boolean closed;

    PostOfficeLink(Socket socket, FrameCodec codec, String name, Consumer<OutgoingServerMessage> replies, Runnable gone)
            throws IOException {
        this.socket = socket;
        this.codec = codec;
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream(), 8 * 1024));
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 8 * 1024));
        FrameCodec.writeGreeting(out);
        out.flush();
        FrameCodec.readGreeting(in);
        this.reader = new Thread(() -> read(replies, gone), "ripv-web-link-" + name);
        reader.setDaemon(true);
        reader.start();
    }

    /** Sends one request as this client (the server stamps user and roles), with a file chunk or null. */
    synchronized void send(long messageId, String mailbox, String body, Priority priority, Attachment file) throws IOException {
        Header h = Header.request(messageId, mailbox, body, priority);
        codec.write(out, new IncomingServerMessage(file == null ? h : h.withAttachment(file)));
    }

    private void read(Consumer<OutgoingServerMessage> replies, Runnable gone) {
        try {
            while (!closed) {
                Message m = codec.read(in);
                if (m instanceof OutgoingServerMessage reply) {
                    replies.accept(reply);
                } else {
                    throw new ProtocolException("the server sent a " + m.getClass().getSimpleName());
                }
            }
        } catch (IOException | RuntimeException e) {
            if (!closed) {
                log.debug("web link {} ended: {}", reader.getName(), e.toString());
            }
        } finally {
            close();
            gone.run();
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
