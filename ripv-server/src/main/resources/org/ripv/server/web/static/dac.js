// A DatabaseServer's IOOS Glider DAC deliveries (?dac MAILBOX --json, docs/dac.md) as the data page
// shows them: per deployment a summary line, a table of its profiles, and the segments that gave none.
// The state is the service's; this module only shapes it into text and rows.

export const DAC_COLUMNS = ['profile', 'mode', 'cast', 'samples', 'dbar', 'QC', 'state', 'why'];

/** "42 s", "3 min", "5 h", "12 days" since; '' when unknown. */
export function ago(seconds) {
  if (seconds == null || !Number.isFinite(seconds)) return '';
  const s = Math.max(0, Math.round(seconds));
  if (s < 120) return `${s} s`;
  if (s < 7200) return `${Math.floor(s / 60)} min`;
  if (s < 172800) return `${Math.floor(s / 3600)} h`;
  return `${Math.floor(s / 86400)} days`;
}

/** One entry per deployment: {title, summary, table: {columns, rows}, notes}. */
export function dacView(deployments) {
  return (deployments || []).map((d) => {
    const counts = Object.entries(d.counts || {}).map(([k, v]) => `${v} ${k}`).join(', ');
    const newest = d.newest_profile
      ? `newest profile ${d.newest_profile}: its data ${ago(d.seconds_since_newest_profile)} ago, written ${ago(d.seconds_since_newest_written)} ago`
      : 'no profile yet';
    return {
      title: `${d.glider} → ${d.destination}`,
      summary: `${(d.profiles || []).length} profile(s)${counts ? ` (${counts})` : ''}; ${newest}`,
      table: {
        columns: DAC_COLUMNS,
        rows: (d.profiles || []).map((p) => [p.name, p.mode, p.direction, String(p.samples),
          `${p.minDbar.toFixed(1)}–${p.maxDbar.toFixed(1)}`, (p.qc || '').replace(/^, /, ''), p.status, p.detail || '']),
      },
      notes: (d.segments || []).map((n) => `${n.segment}: ${n.status}: ${n.detail}`),
    };
  });
}
