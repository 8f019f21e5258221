// The fleet: every MailBox with its call state, live; positions on an offline lat/lon grid.
import { session, PostOffice, bar, ago } from './postoffice.js';
import { drawMap } from './map.js';
import { labels } from './names.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const vehicles = new Map(); // address -> {status, lastContact, lat, lon, calls, latest, track: [[lat, lon]]}
const stateLine = document.getElementById('state');
// Tiles when the server was given --map-tiles, else the offline grid.
const drawTracks = s.mapTiles ? (await import('./tilemap.js')).tileMap(document.getElementById('map'), s.mapTiles)
  : (list) => drawMap(document.getElementById('map'), list);

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
  badge.textContent = { ON_CALL: 'on call', DIVED: 'dived', LOST: 'lost' }[v.state] || (v.available ? 'ready' : 'unknown');
  state.append(badge);
  const cells = [ago(v.lastContact), v.lat == null ? '—' : `${v.lat.toFixed(4)}, ${v.lon.toFixed(4)}`, String(v.calls ?? 0), v.latest || ''];
  tr.append(name, state, ...cells.map((t) => { const td = document.createElement('td'); td.textContent = t; return td; }));
  tr.children[2].className = 'ago';
  tr.children[2].dataset.time = String(v.lastContact || 0);
  tr.dataset.address = address;
  return tr;
}

function render() {
  const body = document.getElementById('vehicles');
  const names = labels([...vehicles.keys()]);
  body.replaceChildren(...[...vehicles.entries()].map(([a, v]) => row(a, v, names.get(a))));
  drawTracks([...vehicles.entries()].map(([a, v]) => ({ name: a, track: v.track })));
}

function takeStatus(m) {
  const session = m.session || {};
  const v = vehicles.get(m.address) || { track: [] };
  Object.assign(v, { available: m.available, state: session.state || 'UNKNOWN', lastContact: session.lastContact || v.lastContact,
    calls: session.calls ?? v.calls, latest: session.lastEvent || v.latest });
  if (session.lat != null) { v.lat = session.lat; v.lon = session.lon; if (!v.track.length) v.track.push([v.lat, v.lon]); }
  vehicles.set(m.address, v);
}

function takeEntry(e, live = true) {
  const v = vehicles.get(e.mailbox);
  if (!v) return;
  v.lastContact = e.time;
  if (e.kind === 'EVENT') {
    v.latest = `${e.event} ${e.text}`.trim();
    if (e.event === 'SURFACED') { v.state = 'ON_CALL'; if (live) v.calls = (v.calls || 0) + 1; }
    if (e.event === 'DIVED') v.state = 'DIVED';
    if (e.event === 'LINK_LOST') v.state = 'LOST';
  }
  if (e.lat != null) { v.lat = e.lat; v.lon = e.lon; v.track.push([e.lat, e.lon]); }
}

po.onPush = (m) => {
  if (m.result && m.result.kind === 'ConsoleBatch') { m.result.entries.forEach(takeEntry); render(); }
};
po.onClose = (why) => { stateLine.textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };

const list = await po.send('', '?mailboxes');
if (list.status === 'ERROR') {
  stateLine.textContent = `Error: ${list.text}`;
} else {
  (list.result?.mailboxes || []).forEach(takeStatus);
  stateLine.textContent = `${vehicles.size} MailBox(es), updated live.`;
  render();
  // All at once: a fleet of 100 answered one by one waits 100 round trips before it is live.
  const watches = await Promise.all([...vehicles.keys()].map((address) => po.send('', `?watch ${address}`)));
  for (const w of watches) {
    if (w.result && w.result.kind === 'ConsoleBatch') w.result.entries.forEach((e) => takeEntry(e, false)); // counted in the status already
  }
  render();
}
// "12 min ago" keeps ticking; only that text changes, so a row never moves under the user's pointer.
setInterval(() => {
  for (const td of document.querySelectorAll('td.ago')) td.textContent = ago(Number(td.dataset.time));
}, 1000);
