/**
 * A query's table on its way through the server in pages (issue 38, {@code org.ripv.messages.TablePages}):
 * each page goes to its client's reply queue, and only once it is written to the client's socket is the
 * service told to send the next ({@code GenericRMIInterface.more}), so the server holds a couple of pages
 * per query, never a whole result, and a client that reads slowly slows its own query and nobody else's.
 */
package org.ripv.server.paging;
