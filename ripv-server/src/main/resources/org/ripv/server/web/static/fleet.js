// The fleet: every MailBox with its call state, live; each vehicle's whole track on the map — the fixes of its transcript
// (30 days, as the public view shows) and the positions the DatabaseServer holds (GPS and dead-reckoned); and the goto
// list each glider runs (`?plan MAILBOX current`, the vehicle page's and the plan page's PlanModel and gliderLayer).
import { session, PostOffice, bar } from './postoffice.js';
import { ago, utc } from './time.js';
import { drawMap, currentLayer, waypointLayer, colour } from './map.js';
import { labels, vehicleName } from './names.js';
import { surfacings, abort, nextCallShort, trackFixes, waypointShort } from './surfacing.js';
import { PlanModel } from './plan-model.js';
import { gliderLayer } from './plan-layers.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const vehicles = new Map(); // address -> {status, lastContact, lat, lon, calls, latest, track: [{lat, lon, t, gps}], seen: Set}
const database = new Map(); // a vehicle's name in the database (the glider's own) -> its positions, as fixes
const stateLine = document.getElementById('state');
const mapBox = document.getElementById('map');
/** Fixes of the transcript: the last TRACK_DAYS days, as the public view has them. */
const TRACK_DAYS = 30;
/** The newest positions the map asks the database for (the data page's own statement, so view-only rules allow it). */
export const POSITIONS = 'SELECT * FROM positions ORDER BY time_utc DESC FETCH FIRST 5000 ROWS ONLY';
// Tiles when the server was given --map-tiles, else the offline grid.
const drawTracks = s.mapTiles ? (await import('./tilemap.js')).tileMap(mapBox, s.mapTiles)
  : (list, focus) => drawMap(mapBox, list, list.flatMap((v, i) => v.layers ? v.layers(colour(i)) : []), focus);
const calls = new Map(); // address -> { records, outlook } of its call records (?surfacings --outlook)
const plans = new Map(); // address -> PlanModel: the goto list it runs (?plan MAILBOX current)
const focus = document.getElementById('map-focus'); // the vehicle the map is fitted to: a fleet may be oceans apart

function row(address, v, label) {
  const tr = document.createElement('tr');
  const name = document.createElement('td');
  const link = document.createElement('a');
  link.href = `/vehicle.html?m=${encodeURIComponent(address)}`;
  link.textContent = label;
  link.title = address;
  name.append(link);
  const state = document.createElement('td');
  const badge = document.createElement('span');
  badge.className = `badge ${v.state}`;
  badge.textContent = { ON_CALL: 'on call', DIVED: 'dived', LOST: 'link lost' }[v.state] || (v.available ? 'ready' : 'unknown');
  state.append(badge);
  const c = calls.get(address);
  const last = c?.records[c.records.length - 1];
  const a = abort(last);
  if (a) { // beside the call state, so a phone (which hides the later columns) shows it too
    const ab = document.createElement('span');
    ab.className = `badge abort${a.fresh ? '' : ' old'}`;
    ab.textContent = a.fresh ? 'new abort' : 'abort';
    ab.title = `${a.text} (${a.detail})`; // the cause in full on the vehicle page
    state.append(' ', ab);
  }
  if (last?.leak === true) {
    const lk = document.createElement('span');
    lk.className = 'badge leak';
    lk.textContent = 'leak';
    lk.title = `leak detect ${Number(last.leak_v).toFixed(2)} V`;
    state.append(' ', lk);
  }
  const cells = [ago(v.lastContact), v.lat == null ? '—' : `${v.lat.toFixed(4)}, ${v.lon.toFixed(4)}`, '', String(v.calls ?? 0), v.latest || ''];
  tr.append(name, state, ...cells.map((t) => { const td = document.createElement('td'); td.textContent = t; return td; }));
  // The last call in one cell: why it surfaced, its battery, and when the next is due.
  const lastCall = tr.children[4];
  lastCall.className = 'last-call';
  const part = (cls, text) => { const sp = document.createElement('span'); sp.className = cls; sp.textContent = text; return sp; };
  if (last) { // a MailBox that printed no surface dialog (a service, a PicoDOS glider) has nothing to say here
    lastCall.append(part('because', last.because || '—'), ' · ', part('battery', last.battery_v == null ? '—' : `${Number(last.battery_v).toFixed(2)} V`),
      document.createElement('br'), part('next-call', c.outlook?.next_call_utc ? `next ${nextCallShort(c.outlook)}` : 'next call not known yet'));
  } else {
    lastCall.textContent = '—';
  }
  tr.children[2].className = 'ago';
  tr.children[2].dataset.time = String(v.lastContact || 0);
  tr.children[2].title = utc(v.lastContact); // the time itself, as every page writes it
  tr.dataset.address = address;
  return tr;
}

/** The map's vehicles: each MailBox's fixes with the database's of the same name, and the database's other vehicles. */
function mapVehicles() {
  const names = new Map([...vehicles.keys()].map((a) => [vehicleName(a).toLowerCase(), a]));
  const list = [...vehicles.entries()].map(([a, v]) => {
    const o = calls.get(a)?.outlook;
    const fixes = trackFixes(o);
    const wpt = o?.wpt_lat == null ? null : { lat: o.wpt_lat, lon: o.wpt_lon };
    const from = o?.fix_lat == null ? null : { lat: o.fix_lat, lon: o.fix_lon };
    const currents = fixes.filter((p) => p.current_e != null);
    const plan = plans.get(a);
    const goto = plan ? plan.current.waypoints.map((p) => ({ lat: p.lat, lon: p.lon })) : [];
    // layers for the offline map; currents, waypoint and goto list as data for the tile map, which draws them with Leaflet
    return { name: a, track: [...v.track, ...fixes, ...(database.get(vehicleName(a).toLowerCase()) || [])], also: [...(wpt ? [wpt] : []), ...goto],
      currents, waypoint: wpt ? { from, to: wpt, words: waypointShort(o) } : null, goto: plan?.current.waypoints.length ? plan.current : null,
      // the goto list under the rest; its fix and leg are the waypoint layer's dashed line already
      layers: (c) => [...(plan ? [gliderLayer(plan, { colour: c, name: a, leg: false })] : []), currentLayer(currents, c),
        ...(wpt ? [waypointLayer(from, wpt, waypointShort(o), c)] : [])] };
  });
  for (const [name, fixes] of database) if (!names.has(name)) list.push({ name: fixes.label, track: fixes });
  return list;
}

function render() {
  const body = document.getElementById('vehicles');
  const names = labels([...vehicles.keys()]);
  body.replaceChildren(...[...vehicles.entries()].map(([a, v]) => row(a, v, names.get(a))));
  drawMapNow();
}

function drawMapNow() {
  const list = mapVehicles();
  const tracked = list.filter((v) => v.track.length).map((v) => v.name);
  if (tracked.join('\n') !== [...focus.options].slice(1).map((o) => o.value).join('\n')) {
    const was = focus.value;
    focus.replaceChildren(new Option('every vehicle', ''), ...tracked.map((n) => new Option(vehicleName(n), n)));
    focus.value = tracked.includes(was) ? was : '';
  }
  drawTracks(list, focus.value);
}
focus.addEventListener('change', drawMapNow);

function addFix(v, lat, lon, t) {
  const key = `${t}/${lat}/${lon}`;
  if (v.seen.has(key)) return;
  v.seen.add(key);
  v.track.push({ lat, lon, t, gps: true }); // the transcript's fixes are the dialog's GPS lines
}

function takeStatus(m) {
  const session = m.session || {};
  const v = vehicles.get(m.address) || { track: [], seen: new Set() };
  Object.assign(v, { available: m.available, state: session.state || 'UNKNOWN', lastContact: session.lastContact || v.lastContact,
    calls: session.calls ?? v.calls, latest: session.lastEvent || v.latest });
  if (session.lat != null) { v.lat = session.lat; v.lon = session.lon; addFix(v, v.lat, v.lon, session.lastContact || 0); }
  vehicles.set(m.address, v);
}

/**
 * The vehicle's call records and outlook, and the goto list it runs, asked again when its call's events come (the
 * record is kept as its dialog ends; a PLAN_CHANGE may put a new list in effect).
 */
async function loadCalls(address) {
  const [d, plan] = await Promise.all([surfacings(po, address),
    po.send('', `?plan ${address} current`).catch((e) => ({ status: 'ERROR', text: String(e) }))]);
  if (!d.error) calls.set(address, d);
  if (plan.status !== 'ERROR' && plan.result?.rows) {
    const model = plans.get(address) || new PlanModel();
    model.setCurrent(plan.result.rows, (plan.text || '').split('\n')[0]);
    plans.set(address, model);
  }
}
const asking = new Map();
function callsSoon(address) {
  clearTimeout(asking.get(address));
  asking.set(address, setTimeout(async () => { await loadCalls(address); render(); }, 800));
}

function takeEntry(e, live = true) {
  const v = vehicles.get(e.mailbox);
  if (!v) return;
  if (live && (e.kind === 'EVENT' || (e.kind === 'LINE' && /Hit Control-C within \d+/.test(e.text || '')))) callsSoon(e.mailbox);
  if (live || e.time > (v.lastContact || 0)) v.lastContact = e.time;
  if (e.kind === 'EVENT' && live) {
    v.latest = `${e.event} ${e.text}`.trim();
    if (e.event === 'SURFACED') { v.state = 'ON_CALL'; v.calls = (v.calls || 0) + 1; }
    if (e.event === 'DIVED') v.state = 'DIVED';
    if (e.event === 'LINK_LOST') v.state = 'LOST';
  }
  if (e.lat != null) { v.lat = e.lat; v.lon = e.lon; addFix(v, e.lat, e.lon, e.time); }
}

/** The positions of every DatabaseServer the user may query; none (and no error shown) when there is none. */
async function databasePositions(addresses) {
  const replies = await Promise.all(addresses.filter((a) => a.startsWith('<DatabaseServer>')).map((db) => po.send(db, POSITIONS)));
  for (const r of replies) {
    const t = r.result;
    if (r.status === 'ERROR' || t?.kind !== 'TableResult') continue; // no data yet, or not allowed: the transcript's fixes still show
    const col = (name) => t.columns.findIndex((c) => c.toLowerCase() === name);
    const [vi, ti, la, lo, so] = ['vehicle', 'time_utc', 'lat', 'lon', 'source'].map(col);
    for (const row of t.rows) {
      const lat = Number(row[la]), lon = Number(row[lo]);
      if (!Number.isFinite(lat) || !Number.isFinite(lon)) continue;
      const name = String(row[vi]).toLowerCase();
      const fixes = database.get(name) || Object.assign([], { label: String(row[vi]) });
      fixes.push({ lat, lon, t: Date.parse(`${String(row[ti]).replace(' ', 'T')}Z`) || 0, gps: row[so] === 'gps' });
      database.set(name, fixes);
    }
  }
}

po.onPush = (m) => {
  if (m.result && m.result.kind === 'ConsoleBatch') { m.result.entries.forEach((e) => takeEntry(e)); render(); }
};
po.onClose = (why) => { stateLine.textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };

const list = await po.send('', '?mailboxes');
if (list.status === 'ERROR') {
  stateLine.textContent = `Error: ${list.text}`;
} else {
  const all = (list.result?.mailboxes || []);
  all.forEach(takeStatus);
  stateLine.textContent = `${vehicles.size} MailBox(es), updated live.`;
  render();
  // All at once: a fleet of 100 answered one by one waits 100 round trips before it is live.
  const since = new Date(Date.now() - TRACK_DAYS * 86400000).toISOString().replace(/\.\d+Z$/, 'Z');
  const addresses = [...vehicles.keys()];
  const [watches, histories] = await Promise.all([
    Promise.all(addresses.map((a) => po.send('', `?watch ${a}`))),
    Promise.all(addresses.map((a) => po.send('', `?history ${a} --since ${since} --last 2000`))),
    databasePositions(all.map((m) => m.address)),
    Promise.all(addresses.filter((a) => !a.startsWith('<DatabaseServer>')).map(loadCalls)),
  ]);
  for (const r of [...histories, ...watches]) {
    if (r.result?.kind === 'ConsoleBatch') r.result.entries.forEach((e) => takeEntry(e, false)); // counted in the status already
  }
  for (const v of vehicles.values()) v.track.sort((a, b) => a.t - b.t);
  render();
  document.body.dataset.ready = 'true';
}
// "12 min ago" keeps ticking; only that text changes, so a row never moves under the user's pointer.
setInterval(() => {
  for (const td of document.querySelectorAll('td.ago')) td.textContent = ago(Number(td.dataset.time));
}, 1000);
// The map is drawn at its size on screen: again when that changes (a phone turned, a window resized).
let resized = null;
window.addEventListener('resize', () => { clearTimeout(resized); resized = setTimeout(drawMapNow, 150); });
