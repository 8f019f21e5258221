// The public view (--public GLOB): map, track and last contact of the vehicles the operator made
// public, for anonymous visitors. Read only: one GET, again every 15 s; no session, no WebSocket.
import { ago, utc } from './time.js';
import { drawMap } from './map.js';

const $ = (id) => document.getElementById(id);
const BADGE = { ON_CALL: 'on call', DIVED: 'dived', LOST: 'lost' };
let draw = null;
let shown = null; // what the map shows

function row(v) {
  const tr = document.createElement('tr');
  tr.dataset.name = v.name;
  const last = v.track[v.track.length - 1];
  const badge = document.createElement('span');
  badge.className = `badge ${v.state}`;
  badge.textContent = BADGE[v.state] || 'unknown';
  const cells = [v.name, badge, ago(v.lastContact), last ? `${last[0].toFixed(4)}, ${last[1].toFixed(4)}` : '—'];
  tr.append(...cells.map((c) => { const td = document.createElement('td'); td.append(c); return td; }));
  tr.children[2].className = 'ago';
  tr.children[2].dataset.time = String(v.lastContact || 0);
  tr.children[2].title = utc(v.lastContact); // the time itself, as every page writes it
  return tr;
}

async function refresh() {
  const r = await fetch('/api/public', { credentials: 'omit' });
  if (r.status === 404) { $('state').textContent = 'This server shows no public view.'; return false; }
  if (!r.ok) { $('state').textContent = 'The vehicles could not be read just now; trying again.'; return true; }
  const p = await r.json();
  if (!draw) {
    draw = p.mapTiles ? (await import('./tilemap.js')).tileMap($('map'), p.mapTiles) : (list) => drawMap($('map'), list);
  }
  $('vehicles').replaceChildren(...p.vehicles.map(row));
  shown = p.vehicles.map((v) => ({ name: v.name, track: v.track }));
  draw(shown);
  $('state').textContent = `${p.vehicles.length} vehicle(s), updated ${utc(Date.now())}.`;
  return true;
}

if (await refresh()) setInterval(refresh, 15000);
// The map is drawn at its size on screen: again when that changes.
window.addEventListener('resize', () => { if (shown) draw(shown); });
setInterval(() => {
  for (const td of document.querySelectorAll('td.ago')) td.textContent = ago(Number(td.dataset.time));
}, 1000);
