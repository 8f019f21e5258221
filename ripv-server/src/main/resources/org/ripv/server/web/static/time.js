// Every time the console shows, in one form on every page: UTC, ISO-like, "2026-11-28 05:40:12 UTC".
// Vehicles, transcripts and the database all keep UTC; a pilot comparing pages never converts.

const pad = (n) => String(n).padStart(2, '0');

/** "2026-11-28 05:40:12 UTC"; '' for no time. */
export function utc(ms) {
  if (ms == null || ms === '' || Number.isNaN(Number(ms)) || !ms) return '';
  return `${day(ms)} ${clock(ms)} UTC`;
}

/** "2026-11-28" (UTC). */
export function day(ms) {
  const d = new Date(Number(ms));
  return `${d.getUTCFullYear()}-${pad(d.getUTCMonth() + 1)}-${pad(d.getUTCDate())}`;
}

/** "05:40:12" (UTC): the console's line stamp, the day being the page's. */
export function clock(ms) {
  const d = new Date(Number(ms));
  return `${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}:${pad(d.getUTCSeconds())}`;
}

/** A database timestamp as text ("2026-11-28 05:40:12.123456789", time_utc columns) in the same form; other text as it is. */
export function utcText(text) {
  const m = /^(\d{4}-\d\d-\d\d)[ T](\d\d:\d\d:\d\d)(\.\d+)?Z?$/.exec(text ?? '');
  return m ? `${m[1]} ${m[2]} UTC` : text;
}

/** Tick labels for a time axis in milliseconds: the day at day steps, the time of day below. */
export function axisValues(ticks, stepMs) {
  return ticks.map((ms, i) => {
    if (stepMs >= 86400000) return day(ms);
    const t = stepMs >= 60000 ? clock(ms).substring(0, 5) : clock(ms);
    return i === 0 || day(ms) !== day(ticks[i - 1]) ? `${t}\n${day(ms)}` : t;
  });
}

/** "12 min ago", ticking; 'never' for no time. */
export function ago(ms) {
  if (!ms) return 'never';
  const s = Math.max(0, Math.round((Date.now() - ms) / 1000));
  if (s < 60) return `${s} s ago`;
  if (s < 3600) return `${Math.round(s / 60)} min ago`;
  if (s < 86400) return `${Math.round(s / 3600)} h ago`;
  return `${Math.round(s / 86400)} days ago`;
}
