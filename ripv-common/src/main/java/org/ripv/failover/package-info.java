/**
 * Lists of servers for a hot standby (docs/operations.md "A hot standby"): services and clients
 * take {@code --server host1[:port],host2[:port]}, try the servers in turn and stay with the one
 * that answers. Only one server of a list serves at a time (the others stand by and listen on
 * nothing), so "whichever answers" is the active one.
 */
package org.ripv.failover;
