/**
 * Service-level benchmarks (YMODEM against the line rate and lrzsz; vis: to JPEG); run through {@code ./ripv bench}.
 * {@link org.ripv.services.bench.SyntheticDba} makes the DBA files the ingest and plot benchmarks (and the services' tests) read.
 */
package org.ripv.services.bench;
