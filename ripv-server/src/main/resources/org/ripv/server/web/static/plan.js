// A vehicle's goto list edited on a map and in a table, both views of one PlanModel (plan-model.js): the list the glider
// runs (?plan current) beside the proposed one; load a file (?plan check), add, move (drag or type) and remove waypoints, edit
// b_args, save the new file into the upload store, check it and keep it as a version (?plan save: the server's FILE:LINE:
// reasons under the form, or the diff against the last version sent; ?plan history lists the versions), send
// it on the next call (?plan send), queue a put (?plan set), and follow every change (?changes) as its events arrive.
import { session, PostOffice, bar } from './postoffice.js';
import { upload, storedName } from './transfer.js';
import { el, button, say, mailboxParam, vehicleNav } from './ui.js';
import { rights } from './rights.js';
import { command } from './address.js';
import { drawMap } from './map.js';
import { PlanModel } from './plan-model.js';
import { PlanView, gliderLayer, proposedLayer, dragEditor } from './plan-layers.js';
import { utcText } from './time.js';

const { mailbox, handle } = mailboxParam();
const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
document.getElementById('name').textContent = `Plan of ${handle}`;
document.title = `RIPV plan ${handle}`;
document.querySelector('main').prepend(vehicleNav(mailbox, 'plan.html'));
const $ = (id) => document.getElementById(id);

const model = new PlanModel();
const view = new PlanView();
let saved = null; // the name the last saved file is stored under
let selected = -1; // the waypoint last touched on the map, drawn larger
let fitted = []; // the places the map was fitted to; kept still while a waypoint is dragged

function input(value, label, cls) {
  return el('input', '', { value, 'aria-label': label, class: cls, autocomplete: 'off', spellcheck: 'false' });
}

/** The waypoint table, drawn from the model; typing goes back into it (and the map follows). */
function renderWaypoints() {
  $('wpts').tBodies[0].replaceChildren(...model.waypoints.map((w, i) => {
    const tr = el('tr', '', { 'data-n': String(i) });
    tr.append(el('td', String(i)), el('td'), el('td'), el('td'), el('td'));
    for (const [k, field, label] of [[1, 'lat', 'latitude'], [2, 'lon', 'longitude'], [3, 'comment', 'comment']]) {
      const box = input(w[field], label, field);
      box.addEventListener('input', () => model.edit(i, field, box.value, 'table'));
      tr.children[k].append(box);
    }
    tr.children[4].append(button('Remove', () => model.remove(i)));
    return tr;
  }));
}

function renderBargs() {
  $('bargs').tBodies[0].replaceChildren(...model.bargs.map(([name, units, value, comment]) => {
    const tr = el('tr', '', { 'data-name': name, 'data-units': units });
    tr.append(el('td', `${name}(${units})`), el('td'), el('td'));
    const v = input(value, `${name} value`, 'value');
    if (name === 'num_waypoints') v.readOnly = true; // counted, never typed: the glider reads exactly this many
    v.addEventListener('input', () => model.setBarg(name, 'value', v.value, 'table'));
    tr.children[1].append(v);
    const c = input(comment, `${name} comment`, 'comment');
    c.addEventListener('input', () => model.setBarg(name, 'comment', c.value, 'table'));
    tr.children[2].append(c);
    return tr;
  }));
}

function drawPlanMap() {
  const canvas = $('plan-map');
  if (!view.dragging) fitted = model.extent();
  const fix = model.current.fix;
  // the vehicle's `also`: places kept in view that are not its track (both lists, the waypoint it heads for)
  drawMap(canvas, [{ name: handle, track: fix ? [[fix.lat, fix.lon]] : [], also: fitted }],
    [gliderLayer(model), proposedLayer(model, view, () => selected)], handle);
  canvas.dataset.waypoints = String(model.points().length);
  // where each proposed waypoint was drawn (CSS pixels from the canvas's top left): what a pointer can grab
  canvas.dataset.dots = JSON.stringify(view.dots.map((d) => [d.i, Math.round(d.px), Math.round(d.py)]));
}

model.onChange((what, from) => {
  if (what === 'waypoints') {
    if (from !== 'table') renderWaypoints();
    const count = document.querySelector("#bargs tr[data-name='num_waypoints'] .value");
    if (count) count.value = String(model.waypoints.length);
  }
  if (what === 'bargs' && from !== 'table') renderBargs();
  if (from !== 'map') drawPlanMap(); // the map redraws itself while dragging
});
dragEditor($('plan-map'), model, view, drawPlanMap, (i) => { selected = i; });

/** What the glider runs: its last fetched goto file or the one in effect, the waypoint it heads for, its fix. */
async function loadCurrent() {
  const r = await po.send('', `?plan ${mailbox} current`);
  if (r.status === 'ERROR') { say($('current-status'), r); return; }
  $('current-status').textContent = `On the glider: ${r.text.split('\n').join(' — ')}`;
  model.setCurrent(r.result?.rows || [], r.text.split('\n')[0]);
}

function fileText(name) {
  return model.fileText(name, s.user, new Date().toISOString());
}

// "  initial_wpt(enum)       -2  # the closest": the b_args as ?plan check prints them.
const BARG = /^ {2}(\w+)\(([^()]*)\)\s+(\S+)(?:\s+# (.*))?$/;

async function load(e) {
  e?.preventDefault();
  const name = $('plan-file').value.trim();
  const r = await po.send('', `?plan ${mailbox} check ${name}`);
  say($('load-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n').slice(0, 2).join(' — ') });
  if (r.status === 'ERROR') return;
  const bargs = r.text.split('\n').slice(r.text.split('\n').indexOf('b_args:') + 1).map((l) => BARG.exec(l)).filter(Boolean)
    .map((m) => [m[1], m[2], m[3], m[4] ?? '']);
  model.load(r.result?.rows || [], bargs);
}

/** A diff as ?plan save and ?plan history print it: "+ " and "- " lines coloured. */
function showDiff(pre, text) {
  const at = text.search(/diff against version |no earlier version of /);
  const lines = at < 0 ? [] : text.slice(at).split('\n');
  pre.replaceChildren(...lines.map((l, i) => el('span', `${l}\n`, i > 0 && /^[+-] /.test(l) ? { class: l[0] === '+' ? 'add' : 'del' } : {})));
  pre.hidden = lines.length === 0;
}

function showProblems(reply) {
  const lines = reply.status === 'ERROR' ? reply.text.split('\n').filter((l) => /^.+?:\d+: /.test(l)) : [];
  $('problems').replaceChildren(...lines.map((l) => el('li', l, { role: 'alert' })));
  $('problems').hidden = lines.length === 0;
}

async function save(e) {
  e.preventDefault();
  const name = $('save-name').value.trim();
  const up = await upload(po, name, new TextEncoder().encode(fileText(name)), 'keep');
  if (up.status === 'ERROR') { say($('save-status'), up); return; }
  saved = storedName(up, name);
  // checked, and kept as the next version of NAME with its diff against the last version sent
  const r = await po.send('', `?plan ${mailbox} save ${saved} as ${name}`);
  say($('save-status'), r.status === 'ERROR' ? { ...r, text: `${saved} was saved but does not pass the check` }
    : { ...r, text: `saved and checked: ${r.text.split('\n')[1]} — ${r.text.split('\n')[0]}` });
  showProblems(r);
  if (r.status === 'ERROR') $('diff').hidden = true; else showDiff($('diff'), r.text);
  $('send').disabled = r.status === 'ERROR';
  $('history-name').value = name;
}

/** The saved versions of a file, who saved each when and whether it was sent; a version's diff on its button. */
async function history(e, version = '') {
  e?.preventDefault();
  const name = $('history-name').value.trim();
  const r = await po.send('', `?plan ${mailbox} history ${name}${version ? ` ${version}` : ''}`);
  say($('history-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n')[0] });
  if (r.status === 'ERROR') { $('versions').replaceChildren(); $('history-diff').hidden = true; return; }
  $('versions').replaceChildren(...(r.result?.rows || []).slice().reverse().map(([n, when, user, , , sent]) => {
    const li = el('li', '', { 'data-version': n, 'data-sent': sent ? 'true' : 'false' });
    li.append(el('span', `version ${n}`, { class: 'state' }), el('span', ` ${utcText(when)}, by ${user}: ${sent ? `sent ${sent}` : 'not sent'}`),
      button('Diff', () => history(null, n)));
    return li;
  }));
  showDiff($('history-diff'), r.text);
}

async function send(e) {
  e.preventDefault();
  if (!saved) { say($('send-status'), { status: 'ERROR', text: 'save the file first' }); return; }
  const r = await po.send('', `?plan ${mailbox} send ${saved} as ${$('send-as').value.trim()}`);
  say($('send-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n')[0] });
  showProblems(r);
  listChanges();
  if (r.status !== 'ERROR') history();
}

async function set(e) {
  e.preventDefault();
  const r = await po.send('', `?plan ${mailbox} set ${$('set-name').value.trim()} ${$('set-value').value.trim()}`);
  say($('set-status'), r);
  listChanges();
}

async function forecast() {
  const name = saved || $('plan-file').value.trim();
  const r = await po.send('', `?plan ${mailbox} forecast ${name}`);
  $('forecast-text').textContent = r.status === 'ERROR' ? `Error: ${r.text}` : r.text;
  $('forecast-text').hidden = false;
}

// "   1  in effect      goto_l10.ma (from goto_l11.ma)  [since …, by alice]" then the reason, indented.
const CHANGE = /^\s*(\d+) {2}(.{14}) (.*)$/;

async function listChanges() {
  const r = await po.send('', `?changes ${mailbox}`);
  if (r.status === 'ERROR') { say($('changes-status'), r); return; }
  const lines = r.text.split('\n');
  $('changes-status').textContent = lines[0];
  const items = [];
  for (let i = 1; i < lines.length; i += 2) {
    const m = CHANGE.exec(lines[i]);
    if (!m) continue;
    const li = el('li', '', { 'data-id': m[1], 'data-state': m[2].trim() });
    li.append(el('span', `#${m[1]} `), el('span', m[2].trim(), { class: 'state' }), el('span', ` ${m[3]}`),
      el('div', (lines[i + 1] || '').trim(), { class: 'why' }));
    items.push(li);
  }
  $('changes').replaceChildren(...items.reverse());
}

$('load-form').addEventListener('submit', load);
$('add-wpt').addEventListener('click', () => {
  // after the last one, a little further on; the map and the table show it, ready to drag or type
  const p = model.points().at(-1);
  if (p) model.add(p.lat + 0.01, p.lon + 0.01); else model.add();
});
$('history-form').addEventListener('submit', history);
$('save-form').addEventListener('submit', save);
$('send-form').addEventListener('submit', send);
$('set-form').addEventListener('submit', set);
$('forecast').addEventListener('click', forecast);
$('refresh-changes').addEventListener('click', listChanges);
// What the permit file lets this user change (the server decides each command again when it is sent).
const SEND = command('?plan', mailbox, 'send', 'goto_l10.ma'), SET = command('?plan', mailbox, 'set', 'x', '0');
const may = (await rights('', [SEND, SET])).commands;
if (!may[SEND]) $('save-card').hidden = true;
if (!may[SET]) $('set-card').hidden = true;
// A change's state moves with PLAN_CHANGE events on the MailBox's console stream.
po.onPush = (m) => {
  if (m.result?.kind !== 'ConsoleBatch' || m.result.mailbox !== mailbox) return;
  const changed = m.result.entries.some((x) => x.event === 'PLAN_CHANGE');
  if (changed) listChanges();
  // a new dialog moves what the glider heads for; a change in effect is the list it runs
  if (changed || m.result.entries.some((x) => x.event === 'DIVED')) loadCurrent();
};
renderBargs();
drawPlanMap();
let resized;
window.addEventListener('resize', () => { clearTimeout(resized); resized = setTimeout(drawPlanMap, 150); });
await Promise.all([listChanges(), loadCurrent(), po.send('', `?watch ${mailbox}`)]);
document.body.dataset.ready = 'true';
