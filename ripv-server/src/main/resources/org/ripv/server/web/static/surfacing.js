// A vehicle's call records and what they say comes next, as the server works them out: `?surfacings MAILBOX --json
// --outlook` (docs/surfacings.md#the-outlook). The server does the arithmetic (CallOutlook); this only words it, so the
// fleet and vehicle pages show the same thing. No DOM here.
import { command } from './address.js';
import { utc, day, clock } from './time.js';

/** Calls the pages ask for: enough for trends and the track, bounded. */
export const CALLS = 200;

/** { records, outlook } of the MailBox, or { error } with the server's words. */
export async function surfacings(po, mailbox, last = CALLS) {
  const r = await po.send('', command('?surfacings', mailbox, '--last', String(last), '--json', '--outlook'));
  if (r.status === 'ERROR') return { error: r.text, records: [], outlook: null };
  try {
    const { records, outlook } = JSON.parse(r.text);
    return { records: records || [], outlook };
  } catch (e) {
    return { error: `the server's answer was not call records: ${e.message}`, records: [], outlook: null };
  }
}

const num = (v) => (v == null || v === '' || !Number.isFinite(Number(v)) ? null : Number(v));
const fixed = (v, n) => (num(v) == null ? null : num(v).toFixed(n));

/** "12 min", "2 h 05 min", "3 days". */
export function span(ms) {
  const s = Math.round(Math.abs(ms) / 1000);
  if (s < 120) return `${s} s`;
  if (s < 7200) return `${Math.round(s / 60)} min`;
  if (s < 172800) return `${Math.floor(s / 3600)} h ${String(Math.floor(s / 60) % 60).padStart(2, '0')} min`;
  return `${Math.round(s / 86400)} days`;
}

/** The next call in words: when, how far off (or how late), and what the interval comes from. */
export function nextCall(o, now = Date.now()) {
  if (!o?.next_call_utc) return o?.calls ? 'not known yet (no interval set, and too few calls to learn one)' : 'no call yet';
  const at = Date.parse(o.next_call_utc);
  const when = at >= now ? `in ${span(at - now)}` : `${span(now - at)} late`;
  return `${utc(at)} (${when}; every ${span(o.interval_s * 1000)}, ${o.interval_from})`;
}

/** The next call, short (the fleet's cell): "09:16:46 UTC (in 4 s)", the day too when it is not today's; its basis in nextCall. */
export function nextCallShort(o, now = Date.now()) {
  if (!o?.next_call_utc) return 'not known';
  const at = Date.parse(o.next_call_utc);
  const when = day(at) === day(now) ? `${clock(at)} UTC` : utc(at);
  return `${when} (${at >= now ? `in ${span(at - now)}` : `${span(now - at)} late`})`;
}

/** The waypoint in words: where, how far and which way from the last fix, and when the glider gets there. */
export function waypoint(o) {
  if (o?.wpt_lat == null) return 'not shown (no c_wpt_lat/c_wpt_lon in the dialog)';
  let s = `${o.wpt_lat.toFixed(5)}, ${o.wpt_lon.toFixed(5)}`;
  if (o.wpt_distance_m != null) s += ` — ${(o.wpt_distance_m / 1000).toFixed(2)} km at ${Math.round(o.wpt_bearing_deg)}°`;
  if (o.wpt_eta_utc) s += `, ETA ${utc(Date.parse(o.wpt_eta_utc))} (${o.wpt_made_good_mps.toFixed(2)} m/s made good)`;
  else if (o.wpt_made_good_mps != null) s += ', no ETA: the glider makes no way toward it against this current';
  else if (o.wpt_distance_m != null) s += ', no ETA yet (needs fixes of two calls)';
  return s;
}

/** The short form for a map label: "12.3 km 045°, ETA 14:05". */
export function waypointShort(o) {
  if (o?.wpt_distance_m == null) return 'waypoint';
  const eta = o.wpt_eta_utc ? `, ETA ${utc(Date.parse(o.wpt_eta_utc)).slice(5, 16)}` : '';
  return `waypoint ${(o.wpt_distance_m / 1000).toFixed(1)} km ${String(Math.round(o.wpt_bearing_deg)).padStart(3, '0')}°${eta}`;
}

/** The abort a record shows: { text, fresh } (fresh: an abort not seen at an earlier surfacing), or null. */
export function abort(r) {
  if (!r || !(num(r.abort_total) > 0)) return null;
  const fresh = r.new_abort === true || r.new_abort === 'true';
  return { fresh, text: `${fresh ? 'new abort' : 'last abort'}: ${r.abort_cause || 'cause not given'}`,
    detail: [r.abort_details, r.abort_time && `at ${r.abort_time}`, `${r.abort_total} since reset`].filter(Boolean).join(', ') };
}

/** The last call's record as [key, label, text] rows for the vehicle page's card. */
export function lastCall(r, o, now = Date.now()) {
  if (!r) return [['none', 'Last call', 'no surface dialog read from this vehicle yet']];
  const fix = num(r.gps_lat) == null ? `none${r.gps_problem ? ` (${r.gps_problem})` : ''}`
    : `${num(r.gps_lat).toFixed(5)}, ${num(r.gps_lon).toFixed(5)}` + (num(r.gps_age_s) == null ? '' : ` (${fixed(r.gps_age_s, 0)} s old at the call)`);
  const leak = num(r.leak_v) == null ? 'no leak sensor shown' : `${r.leak === true || r.leak === 'true' ? 'LEAK' : 'dry'} (${fixed(r.leak_v, 2)} V)`;
  const a = abort(r);
  const current = o?.current_mps == null ? 'not shown' : `${o.current_mps.toFixed(3)} m/s toward ${Math.round(o.current_toward_deg)}°`;
  const t = Date.parse(r.time_utc);
  const coulombs = o?.coulomb_sensor && num(r[o.coulomb_sensor]) != null ? `${fixed(r[o.coulomb_sensor], 2)} Ah (${o.coulomb_sensor})` : null;
  return [
    ['time', 'Time', `${utc(t)} (${span(now - t)} ago)`],
    ['because', 'Because', r.because || '—'],
    ['mission', 'Mission', r.mission || '—'],
    ['fix', 'GPS fix', fix],
    ['battery', 'Battery', num(r.battery_v) == null ? '—' : `${fixed(r.battery_v, 2)} V`],
    ['coulombs', 'Charge used', coulombs || '—'],
    ['vacuum', 'Vacuum', num(r.vacuum_inhg) == null ? '—' : `${fixed(r.vacuum_inhg, 2)} inHg`],
    ['leak', 'Leak', leak],
    ['abort', 'Aborts', a ? `${a.text} (${a.detail})` : 'none since reset'],
    ['current', 'Depth-averaged current', current],
    ['sog', 'Over ground', o?.sog_mps == null ? 'not known (needs fixes of two calls)' : `${o.sog_mps.toFixed(3)} m/s toward ${Math.round(o.cog_deg)}°`],
    ['next', 'Next call', nextCall(o, now)],
    ['waypoint', 'Waypoint', waypoint(o)],
  ];
}

/** The trend charts: [key, title, unit] of each series the outlook carries (CallOutlook.SERIES). */
export const TRENDS = [
  ['battery_v', 'Battery', 'V'],
  ['vacuum_inhg', 'Vacuum', 'inHg'],
  ['leak_v', 'Leak detect', 'V'],
  ['coulomb_amphr', 'Charge used', 'Ah'],
  ['current_mps', 'Current', 'm/s'],
];

/** The outlook's track as the map's fixes (GPS and dead-reckoned) and the points that carry a current. */
export function trackFixes(o) {
  return (o?.track || []).map((p) => ({ lat: p.lat, lon: p.lon, t: p.t, gps: p.gps, current_e: p.current_e, current_n: p.current_n }));
}
