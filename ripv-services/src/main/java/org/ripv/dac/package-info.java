/**
 * IOOS Glider DAC delivery: a glider's flight and science files become one NetCDF profile file
 * per dive and per climb, as the U.S. IOOS National Glider Data Assembly Center takes them
 * (template {@code IOOS_Glider_NetCDF_v2.0}, docs/dac.md).
 *
 * <p>The pipeline, one class a step: {@link org.ripv.dac.SegmentReader} decodes the files with
 * the project's Slocum decoder ({@link org.ripv.services.ingest.SlocumBinaryReader}, public API
 * only) into a {@link org.ripv.dac.Segment}; {@link org.ripv.dac.ProfileSplitter} finds the
 * pressure's turning points as pyglider does; {@link org.ripv.dac.Profiles} derives pressure in
 * dbar, depth, salinity and density ({@link org.ripv.dac.Gsw}, TEOS-10) and the profile's
 * position and current; {@link org.ripv.dac.Qartod} flags the values as ioos_qc does, configured
 * by {@link org.ripv.dac.QcConfig} (ioos_qc's YAML); {@link org.ripv.dac.ProfileWriter} writes
 * the file (NetCDF-3 classic) from {@link org.ripv.dac.CdlTemplate} and
 * {@link org.ripv.dac.Metadata}; {@link org.ripv.dac.ProfileChecker} checks it as the DAC's
 * checker would. {@link org.ripv.dac.DacCommand} is {@code ripv dac}.
 *
 * <p>Every refusal is a {@link org.ripv.dac.DacException} whose message names the file and the
 * reason; a file is written beside its place and renamed, so nothing half-written is left.
 */
package org.ripv.dac;
