/**
 * The server's HTTP landing page (JDK HttpServer): what the server is, the client jar and a JNLP for Web Start launchers, and an upload form with the thesis's CGI rules.
 */
package org.ripv.server.http;
