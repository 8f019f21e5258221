/**
 * The RIPVServer broker (thesis figure 5.3): the RIPV Post Office and its TaskManager, the
 * {@code ?} commands, the launcher and its configuration. The service side lives in
 * {@link org.ripv.server.services}, the requests awaiting a service in
 * {@link org.ripv.server.requests}, the client side in {@link org.ripv.server.clients}.
 * What stays here besides RIPVServer, ServerTaskManager, ServerCommands and the launcher reaches
 * into RIPVServer's package-private state (its service table, secret, locks, pending requests,
 * permits, files), which would otherwise have to be public: ClientDispatch, InternalCalls,
 * OutboundListener, PublicVehicles, RequestCancels, ServerRemote, ServiceAdmission,
 * ServiceQueries, ServiceReplies and WorkflowBridge. DownloadRights and DownloadAttachments
 * serve only the command paths here and throw ServerCommands' refusal; ServerState opens the
 * store from ServerConfig and SessionOptions, which are the launcher's public configuration
 * (tests build them); Threads names RIPVServer's threads.
 * Package-private except what launchers and tests need.
 */
package org.ripv.server;
