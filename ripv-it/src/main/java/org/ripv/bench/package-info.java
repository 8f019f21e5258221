/**
 * The benchmarks of docs/performance.md; each reports against a baseline measured in the same run.
 */
package org.ripv.bench;
