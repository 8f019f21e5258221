// The fleet's pending plan changes (?changes without a MailBox): for each vehicle the user may read, the changes its
// dialogs have not settled yet, with their state and age, each vehicle linked to its plan page. Redrawn on every
// PLAN_CHANGE event of a watched vehicle, and each minute so the ages move.
import { session, PostOffice, bar } from './postoffice.js';
import { el } from './ui.js';
import { vehicleName } from './names.js';
import { ago, utcText } from './time.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const $ = (id) => document.getElementById(id);
const watched = new Set();

async function list() {
  const r = await po.send('', '?changes');
  if (r.status === 'ERROR') { $('status').textContent = `Error: ${r.text}`; $('status').setAttribute('role', 'alert'); return; }
  $('status').textContent = r.text.split('\n')[0];
  const byVehicle = new Map();
  for (const [id, mailbox, change, state, since, user, , detail, queued] of r.result?.rows || []) {
    if (!byVehicle.has(mailbox)) byVehicle.set(mailbox, []);
    byVehicle.get(mailbox).push({ id, change, state, since, user, detail, queued });
  }
  $('vehicles').replaceChildren(...[...byVehicle].map(([mailbox, changes]) => {
    const box = el('section', '', { class: 'vehicle-changes', 'data-mailbox': mailbox });
    const h = el('h3');
    h.append(el('a', vehicleName(mailbox), { href: `/plan.html?m=${encodeURIComponent(mailbox)}` }), el('span', ` (${changes.length})`));
    const table = el('table', '', { class: 'plan changes-table' });
    const head = el('tr');
    for (const t of ['#', 'Change', 'State', 'Since', 'Age', 'By']) head.append(el('th', t));
    table.append(el('thead'), el('tbody'));
    table.tHead.append(head);
    for (const c of changes) {
      const tr = el('tr', '', { 'data-id': c.id, 'data-state': c.state });
      const age = Date.parse(c.queued);
      tr.append(el('td', c.id), el('td', c.change), el('td', c.state, { class: 'state' }), el('td', utcText(c.since)),
        el('td', ago(age), { 'data-queued': String(age) }), el('td', c.user));
      const why = el('tr', '', { class: 'why' });
      why.append(el('td'), el('td', c.detail, { colspan: '5' }));
      table.tBodies[0].append(tr, why);
    }
    box.append(h, el('div', '', { class: 'scroll' }));
    box.lastChild.append(table);
    if (!watched.has(mailbox)) { watched.add(mailbox); po.send('', `?watch ${mailbox}`); }
    return box;
  }));
}

po.onPush = (m) => {
  if (m.result?.kind === 'ConsoleBatch' && m.result.entries.some((x) => x.event === 'PLAN_CHANGE')) list();
};
$('refresh').addEventListener('click', list);
setInterval(list, 60_000);
await list();
document.body.dataset.ready = 'true';
