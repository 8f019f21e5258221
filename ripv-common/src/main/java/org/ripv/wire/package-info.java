/**
 * The client socket protocol: a greeting, then length-prefixed frames each holding one message read with its own filtered ObjectInputStream (docs/protocol.md).
 */
package org.ripv.wire;
