// A vehicle's files: ymodem/zmodem transfers with the vehicle (the CLI's commands, sent to its MailBox), the download
// store (what vehicles sent; fetched into the browser with ?download, which the server's DownloadRights guards) and the
// upload store (?upload with FILE_EXISTS / keep / replace decided by the server).
import { session, PostOffice, bar } from './postoffice.js';
import { upload, download, save, storedName, progressText } from './transfer.js';
import { el, button, say, mailboxParam, vehicleNav } from './ui.js';
import { rights } from './rights.js';
import { utc } from './time.js';

const { mailbox, handle } = mailboxParam();
const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
document.getElementById('name').textContent = `Files of ${handle || 'the server'}`;
document.title = `RIPV files ${handle}`;
document.querySelector('main').prepend(vehicleNav(mailbox, 'files.html'));
const $ = (id) => document.getElementById(id);

function size(n) {
  return n < 10240 ? `${n} B` : n < 10485760 ? `${Math.round(n / 1024)} KB` : `${(n / 1048576).toFixed(1)} MB`;
}

const when = utc;

// A download is listed as FOLDER/NAME; the folder of a vehicle's files begins with its handle and '@'.
function mine(name) {
  const slash = name.indexOf('/');
  return slash > 0 && name.substring(0, slash).toLowerCase().startsWith(`${handle.toLowerCase()}@`);
}

async function listDownloads() {
  const r = await po.send('', '?dlfiles');
  if (r.status === 'ERROR') { say($('download-status'), r); return; }
  const all = $('all-downloads').checked;
  const files = (r.result?.files || []).filter((f) => all || mine(f.name)).sort((a, b) => b.modified - a.modified);
  $('download-status').textContent = files.length ? `${files.length} file(s)` : 'No files from this vehicle yet.';
  $('downloads').replaceChildren(...files.map((f) => {
    const tr = el('tr', '', { 'data-name': f.name });
    // The row's button is Download, and Cancel while its chunks come.
    let stop = null;
    const get = button('Download', async () => {
      if (stop) { stop.abort(); return; }
      stop = new AbortController();
      get.textContent = 'Cancel';
      const got = await download(po, f.name, (done, total) => { $('download-status').textContent = progressText(`${f.name}`, done, total); }, stop.signal);
      stop = null;
      get.textContent = 'Download';
      if (got.error) { say($('download-status'), got.error); return; }
      save(got.blob, f.name);
      $('download-status').textContent = `Downloaded ${f.name} (${size(got.blob.size)}).`;
    });
    tr.append(el('td', f.name), el('td', size(f.size)), el('td', when(f.modified)), el('td'));
    tr.lastChild.append(get);
    return tr;
  }));
}

async function listUploads() {
  const r = await po.send('', '?ulfiles');
  if (r.status === 'ERROR') { say($('upload-status'), r); return; }
  const files = (r.result?.files || []).sort((a, b) => b.modified - a.modified);
  $('uploads').replaceChildren(...files.map((f) => {
    const tr = el('tr', '', { 'data-name': f.name });
    tr.append(el('td', f.name), el('td', size(f.size)), el('td', when(f.modified)));
    return tr;
  }));
}

// ymodem:get / ymodem:put and their zmodem twins: the words the CLI and the workflow steps send to the vehicle.
// Cancel stops the one this page started (?cancel with its id).
let running = null;
const transfer = async (verb) => {
  const names = $('transfer-names').value.trim();
  if (!names) { say($('transfer-reply'), { status: 'ERROR', text: `${verb} needs a file name or pattern` }); return; }
  for (const b of $('transfer-buttons').children) b.disabled = true;
  $('transfer-reply').textContent = '';
  const req = po.send(mailbox, `${verb} ${names}`, 'normal', (p) => {
    const x = p.result;
    $('transfer-progress').textContent = x?.kind === 'Progress' && x.total > 0
      ? progressText(x.what || verb, x.done, x.total) + (x.ratePerSecond > 0 ? `, ETA ${Math.round((x.total - x.done) / x.ratePerSecond)} s` : '')
      : p.text;
  });
  running = req.id;
  $('transfer-cancel').hidden = false;
  const r = await req;
  running = null;
  $('transfer-cancel').hidden = true;
  for (const b of $('transfer-buttons').children) b.disabled = false;
  $('transfer-progress').textContent = '';
  say($('transfer-reply'), r);
  if (verb.endsWith(':get')) listDownloads();
};
$('transfer-cancel').addEventListener('click', async () => {
  if (running != null) say($('transfer-reply'), await po.cancel(running));
});
// The verbs the permit file lets this user send to the vehicle, whatever their role is called.
const VERBS = ['ymodem:get', 'ymodem:put', 'zmodem:get', 'zmodem:put'];
const may = (await rights(mailbox, VERBS.map((v) => `${v} *`))).commands;
const allowed = VERBS.filter((v) => may[`${v} *`]);
$('transfers').hidden = allowed.length === 0;
$('transfer-buttons').append(...allowed.map((v) => button(v, () => transfer(v))));

let uploading = null;
$('upload-cancel').addEventListener('click', () => uploading?.abort());
$('upload-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const file = $('upload-file').files[0];
  if (!file) { say($('upload-status'), { status: 'ERROR', text: 'choose a file first' }); return; }
  $('upload').disabled = true;
  uploading = new AbortController();
  $('upload-cancel').hidden = false;
  const bytes = new Uint8Array(await file.arrayBuffer());
  const r = await upload(po, file.name, bytes, $('if-exists').value, (done, total) => {
    $('upload-status').textContent = progressText(`Uploading ${file.name}`, done, total);
  }, uploading.signal);
  uploading = null;
  $('upload-cancel').hidden = true;
  $('upload').disabled = false;
  say($('upload-status'), r);
  if (r.status !== 'ERROR') {
    $('transfer-names').value = storedName(r, file.name);
    listUploads();
  }
});
$('all-downloads').addEventListener('change', listDownloads);
$('refresh-downloads').addEventListener('click', listDownloads);
await Promise.all([listDownloads(), listUploads()]);
document.body.dataset.ready = 'true';
