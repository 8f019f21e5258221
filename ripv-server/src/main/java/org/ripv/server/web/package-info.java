/**
 * The web console (issue 21): the server's HTTP port on Jetty 12. A browser that logs in becomes
 * a client of the Post Office like a socket client — each page's WebSocket is one
 * {@link org.ripv.server.web.ConsoleSocket}, an in-process client the server adopts, with no
 * thread or socket of its own ({@link org.ripv.server.web.PostOfficeDoor}) — so permits, MailBox locks, priorities, deadlines, transcript and audit are the socket port's
 * own; nothing here decides what a user may do. One {@code Handler} per concern
 * ({@link org.ripv.server.web.LandingHandler}, {@link org.ripv.server.web.LoginHandler},
 * {@link org.ripv.server.web.UploadHandler}, {@link org.ripv.server.web.SecurityHeaders},
 * {@link org.ripv.server.web.HttpsRedirect} for plain HTTP on the TLS port, and
 * {@link org.ripv.server.web.RightsHandler}, which tells a page what the permit file lets its user
 * send so it shows only those controls — the server still decides each command), the
 * pages are static HTML and one ES module each (resources {@code org/ripv/server/web/static}),
 * Leaflet and uPlot come from their WebJars. The one exception to "a logged-in client" is the
 * public view ({@link org.ripv.server.web.PublicHandler}, {@code --public GLOB}, off by default):
 * read only, four fields of the vehicles the operator named, for visitors with no log-in.
 * docs/web.md.
 */
package org.ripv.server.web;
