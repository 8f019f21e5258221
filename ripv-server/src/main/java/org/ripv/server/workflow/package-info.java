/**
 * Work queued for a vehicle that runs when it calls (docs/workflows.md): workflow files and
 * their parser ({@link org.ripv.server.workflow.WorkflowParser}), the per-MailBox queues kept in
 * the data directory ({@link org.ripv.server.workflow.WorkflowQueues}), the runner that starts
 * them on a SURFACED event and sends each step through the server's normal request path
 * ({@link org.ripv.server.workflow.Workflows}), and the receipts each run leaves. A run is
 * {@code Runner} with its parts: {@code CallGate} (the call, waiting at a step boundary),
 * {@code LockTurn} (the operator lock, pause and resume), {@code StepRequests} (a step's request
 * and reply), {@code FetchStep} ({@code ymodem:get}), {@code Outcome} and {@code RunEnd}.
 *
 * <p>The package sees the server only through {@link org.ripv.server.workflow.WorkflowHost}, which
 * {@code org.ripv.server} implements; nothing here reaches into the broker's internals.
 */
package org.ripv.server.workflow;
