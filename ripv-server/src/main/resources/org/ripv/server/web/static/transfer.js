// Files between the browser and the server's stores, in the chunks the CLI sends: ?upload NAME OFFSET TOTAL [MODE]
// with the chunk attached, and ?download NAME OFFSET LENGTH. The server decides every rule (FILE_EXISTS, the replace
// right, quotas, DownloadRights); this only moves bytes and reports progress.

// Raw bytes per upload chunk: base64 of it fits the socket's 64 KiB message limit (FileChunks.MAX_CHUNK on the server).
const UP_CHUNK = 46 * 1024;
const DOWN_CHUNK = 256 * 1024;

function toBase64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

function fromBase64(text) {
  const s = atob(text);
  const bytes = new Uint8Array(s.length);
  for (let i = 0; i < s.length; i++) bytes[i] = s.charCodeAt(i);
  return bytes;
}

/**
 * Uploads bytes as NAME; mode '' refuses a taken name (FILE_EXISTS), 'keep' stores under a new free name, 'replace'
 * replaces (a right of its own). Resolves with the last reply: an ERROR, or the one naming where it was stored. An
 * aborted signal stops it between chunks and drops what the server holds of it (?upload-cancel).
 */
export async function upload(po, name, bytes, mode, onProgress = () => {}, signal = null) {
  const suffix = mode ? ` ${mode}` : '';
  let offset = 0;
  let last;
  do {
    if (signal?.aborted) {
      await po.send('', `?upload-cancel ${name}`); // the server drops the part it holds
      return { status: 'ERROR', error: 'CANCELLED', text: `upload of ${name} cancelled at ${offset} of ${bytes.length} bytes; nothing stored` };
    }
    const chunk = bytes.subarray(offset, Math.min(bytes.length, offset + UP_CHUNK));
    last = await po.send('', `?upload ${name} ${offset} ${bytes.length}${suffix}`, 'normal', () => {},
      { file: name, data: toBase64(chunk) });
    if (last.status === 'ERROR') return last;
    offset += chunk.length;
    onProgress(offset, bytes.length);
  } while (offset < bytes.length);
  return last;
}

/** The name an upload's last reply says the file was stored under. */
export function storedName(reply, asked) {
  return reply.result?.kind === 'FileListing' && reply.result.files.length ? reply.result.files[0].name : asked;
}

/** Fetches a file of the download store; resolves with { blob } or { error: reply }; an aborted signal stops it between chunks. */
export async function download(po, name, onProgress = () => {}, signal = null) {
  const parts = [];
  let offset = 0;
  let total = 0;
  do {
    if (signal?.aborted) return { error: { status: 'ERROR', error: 'CANCELLED', text: `download of ${name} cancelled at ${offset} of ${total} bytes` } };
    const r = await po.send('', `?download ${name} ${offset} ${DOWN_CHUNK}`);
    if (r.status === 'ERROR') return { error: r };
    const c = r.result;
    if (c?.kind !== 'FileData' || typeof c.data !== 'string' || c.offset !== offset) return { error: { status: 'ERROR', text: `no chunk at offset ${offset} of ${name}` } };
    parts.push(fromBase64(c.data));
    offset += c.bytes;
    total = c.total;
    onProgress(offset, total);
    if (c.bytes === 0 && offset < total) return { error: { status: 'ERROR', text: `${name} ended early at ${offset} bytes` } };
  } while (offset < total);
  return { blob: new Blob(parts, { type: 'application/octet-stream' }) };
}

/** Hands a blob to the browser's own download, named as the file's last part. */
export function save(blob, name) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name.substring(name.lastIndexOf('/') + 1);
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 60000);
}

/** "12 KB / 64 KB (19 %)" */
export function progressText(what, done, total) {
  const kb = (n) => (n < 10240 ? `${n} B` : `${Math.round(n / 1024)} KB`);
  return `${what}: ${kb(done)} / ${kb(total)}` + (total > 0 ? ` (${Math.round((100 * done) / total)} %)` : '');
}
