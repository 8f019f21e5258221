/**
 * Handing a fetched file from the service that fetched it to the service that ingests it, without
 * the server relaying the bytes (issue 34). The server decides rights and records the file as
 * before; then it signs a one-use {@link org.ripv.handout.HandoutTicket} per file with the holding
 * service's session token and sends the ticket, not the bytes, in the {@code ingest} request. The
 * ingesting service fetches the bytes from the holder in bounded chunks
 * ({@link org.ripv.handout.HandoutCollector}); the holder keeps what it fetched for a while and
 * checks every ticket ({@link org.ripv.handout.Handouts}). When that fails — the holder is behind
 * NAT, a firewall is in the way, the file was let go — the server relays the bytes as before.
 * docs/security.md#handing-files-between-services, docs/architecture.md.
 *
 * <p>Threads: none of its own. {@code Handouts} is called on the holder's RMI threads and its
 * MailBoxes' inbox assistants; {@code HandoutCollector} runs on the ingesting MailBox's inbox
 * assistant.
 */
package org.ripv.handout;
