/**
 * The state the server keeps beyond one run, behind one interface ({@link org.ripv.server.store.StateStore}):
 * vehicle transcripts, workflow queues, fetched-file lists and receipts, notification
 * subscriptions and the audit trail (docs/operations.md, "The state store"). Users' log-in
 * sessions are not kept.
 *
 * <p>Two implementations: {@link org.ripv.server.store.EmbeddedStateStore}, files in the data
 * directory in the layout earlier versions wrote (the default), and
 * {@link org.ripv.server.store.PostgresStateStore}, tables in a PostgreSQL database given by a
 * JDBC URL ({@code ripv server --state-db jdbc:postgresql://...}), which a second server can
 * share. {@link org.ripv.server.store.StateStores#open} picks one from a
 * {@link org.ripv.server.store.StoreLocation}.
 *
 * <p>The owners of each kind of state keep its format (a workflow queue is a properties text, a
 * transcript entry a JSON line); a store keeps the texts whole: a document is replaced entirely
 * or not at all, and an append of a batch lands entirely or not at all.
 */
package org.ripv.server.store;
