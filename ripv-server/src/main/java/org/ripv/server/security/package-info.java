/**
 * Defences of the server's doors (docs/security.md): who may hold a connection before logging in
 * and for how long ({@link org.ripv.server.security.ConnectionGate}), how fast passwords may be
 * guessed ({@link org.ripv.server.security.LoginThrottle}, {@link org.ripv.server.security.LoginPool}),
 * the audit trail ({@link org.ripv.server.security.Audit}, logger {@code ripv.audit}), the server's
 * own TLS certificate ({@link org.ripv.server.security.SelfSignedTls}), the registry that only the
 * server may bind in ({@link org.ripv.server.security.RegistryGuard}) and the challenge–response a
 * service registers with ({@link org.ripv.server.security.ServiceChallenges}).
 */
package org.ripv.server.security;
