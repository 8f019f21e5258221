/**
 * Service-level benchmarks (YMODEM against the line rate and lrzsz; vis: to JPEG); run through {@code ./ripv bench}.
 */
package org.ripv.services.bench;
