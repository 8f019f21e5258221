// The DatabaseServer's views and (for users the permit file lets send any SQL) a SQL box, and
// vis:track/depth/profile drawn in the page. Everything goes to the services through the Post Office
// with the user's rights: the page hides what the server would refuse, the server refuses it anyway.
import { session, PostOffice, bar } from './postoffice.js';
import { tableElement, csv, download } from './table.js';
import { drawChart, chartCsv, chartPng, chartSize } from './chart.js';
import { command, NotAName } from './address.js';
import { dacView } from './dac.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const $ = (id) => document.getElementById(id);
po.onClose = (why) => { $('state').textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };

// The views' statements; a permit file can allow exactly these (docs/web.md).
export const VIEWS = {
  positions: 'SELECT * FROM positions ORDER BY time_utc DESC FETCH FIRST 1000 ROWS ONLY',
  latest: 'SELECT * FROM latest ORDER BY vehicle, sensor',
  dives: 'SELECT * FROM dives ORDER BY start_utc DESC',
};
const SQL_PROBE = 'VALUES (1)'; // runs nothing: a user the permit file lets send this may send any SQL

function fill(select, addresses) {
  select.replaceChildren(...addresses.map((a) => { const o = document.createElement('option'); o.value = a; o.textContent = a; return o; }));
}

const list = await po.send('', '?mailboxes');
const addresses = (list.result?.mailboxes || []).map((m) => m.address);
const databases = addresses.filter((a) => a.startsWith('<DatabaseServer>'));
const plotters = addresses.filter((a) => a.startsWith('<DataVisServer>'));
fill($('database'), databases);
fill($('datavis'), plotters);
fill($('dac-database'), databases);
$('state').textContent = databases.length
  ? `${databases.length} database(s), ${plotters.length} plotter(s).`
  : 'No DatabaseServer is registered: start one (ripv service database).';

let lastTable = null;
async function query(sql) {
  const db = $('database').value;
  if (!db) return;
  $('table-state').textContent = 'Running…';
  const r = await po.send(db, sql);
  if (r.status === 'ERROR') {
    $('table-state').textContent = `Error: ${r.text} [${r.error}]`;
    $('table').replaceChildren();
    $('table-csv').hidden = true;
    return r;
  }
  const t = r.result;
  if (t?.kind === 'TableResult') {
    lastTable = t;
    $('table').replaceChildren(tableElement(t));
    $('table-state').textContent = `${r.text}${t.truncated ? ' (cut at the row limit)' : ''}`;
    download($('table-csv'), 'table.csv', new Blob([csv(t.columns, t.rows)], { type: 'text/csv' }));
    const vi = t.columns.findIndex((c) => c.toLowerCase() === 'vehicle');
    if (vi >= 0) {
      const names = [...new Set(t.rows.map((row) => row[vi]))];
      $('vehicles').replaceChildren(...names.map((n) => { const o = document.createElement('option'); o.value = n; return o; }));
      if (!$('vehicle').value && names.length) $('vehicle').value = names[0];
    }
  } else {
    $('table').replaceChildren();
    $('table-state').textContent = r.text;
    $('table-csv').hidden = true;
  }
  return r;
}

for (const b of document.querySelectorAll('button[data-view]')) b.addEventListener('click', () => query(VIEWS[b.dataset.view]));
$('sql-form').addEventListener('submit', (e) => { e.preventDefault(); if ($('sql').value.trim()) query($('sql').value.trim()); });

// The SQL box shows only when the server lets this user send any SQL to the database.
if (databases.length) {
  const probe = await po.send(databases[0], SQL_PROBE);
  $('sql-form').hidden = probe.status === 'ERROR' && probe.error === 'FORBIDDEN';
  await query(VIEWS.positions);
}

let plot = null;
$('chart-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const kind = $('plot').value;
  const vehicle = $('vehicle').value.trim();
  const sensor = $('sensor').value.trim();
  if (!vehicle || (kind === 'profile' && !sensor)) {
    $('chart-state').textContent = kind === 'profile' ? 'Give a vehicle and a sensor.' : 'Give a vehicle.';
    return;
  }
  const db = $('database').value;
  let body;
  try { // each part one word: a vehicle name from the data cannot add options to the command
    body = command(`vis:${kind}`, vehicle, ...(kind === 'profile' ? [sensor] : []), ...(databases.length > 1 ? [`db=${db}`] : []));
  } catch (err) {
    if (!(err instanceof NotAName)) throw err;
    $('chart-state').textContent = `Error: ${err.message}`;
    return;
  }
  $('chart-state').textContent = `Drawing ${body}…`;
  const r = await po.send($('datavis').value, body);
  if (r.status === 'ERROR') { $('chart-state').textContent = `Error: ${r.text} [${r.error}]`; return; }
  const chart = r.result?.chart;
  if (!chart) { $('chart-state').textContent = `${r.text} (this plotter sends a picture only: see ${r.result?.name} in the files)`; return; }
  if (plot) plot.destroy();
  plot = drawChart($('chart'), chart, $('readout'));
  $('chart-state').textContent = `${r.text}. Drag to zoom, double-click to zoom out.`;
  const base = (r.result.name || 'chart').replace(/\.jpg$/, '');
  download($('chart-csv'), `${base}.csv`, new Blob([chartCsv(chart)], { type: 'text/csv' }));
  download($('chart-png'), `${base}.png`, await chartPng(plot, chart.title));
});
// A phone turned, a window resized: the chart follows the page's width.
window.addEventListener('resize', () => { if (plot) plot.setSize(chartSize($('chart'))); });

// The DAC deliveries of the chosen DatabaseServer: what the service's own state says (?dac MAILBOX --json).
async function showDac() {
  const db = $('dac-database').value;
  if (!db) { $('dac-state').textContent = 'No DatabaseServer.'; return; }
  $('dac-state').textContent = 'Asking…';
  const r = await po.send('', `?dac ${db} --json`);
  if (r.status === 'ERROR') {
    $('dac-state').textContent = `Error: ${r.text} [${r.error}]`;
    $('dac-deployments').replaceChildren();
    return;
  }
  let view;
  try {
    view = dacView(JSON.parse(r.text));
  } catch (e) {
    $('dac-state').textContent = `The service's answer is not the deliveries' JSON: ${e.message}`;
    return;
  }
  $('dac-state').textContent = view.length ? `${view.length} deployment(s).` : 'No DAC deployment on this DatabaseServer (docs/dac.md: --dac FILE).';
  $('dac-deployments').replaceChildren(...view.map((v) => {
    const box = document.createElement('div');
    box.className = 'dac-deployment';
    const h = document.createElement('h3');
    h.textContent = v.title;
    const p = document.createElement('p');
    p.className = 'dac-summary';
    p.textContent = v.summary;
    const scroll = document.createElement('div');
    scroll.className = 'scroll';
    scroll.append(tableElement(v.table));
    const notes = document.createElement('ul');
    notes.className = 'dac-notes';
    notes.replaceChildren(...v.notes.map((n) => { const li = document.createElement('li'); li.textContent = n; return li; }));
    box.append(h, p, scroll, notes);
    return box;
  }));
}
$('dac-refresh').addEventListener('click', showDac);
$('dac-database').addEventListener('change', showDac);
if (databases.length) showDac();
