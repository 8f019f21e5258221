/**
 * What travels between the parts of RIPV (thesis 5.2.5): {@link org.ripv.messages.Message} = Header + Footer, the four message types, the IDs of Appendix B, and the closed set of typed results. Every class here is on the wire allowlist ({@link org.ripv.wire.WireFilter}).
 */
package org.ripv.messages;
