import { utcText } from './time.js';

// A TableResult as an HTML table (every cell set with textContent: database text is never HTML), and as CSV.
export function tableElement(t) {
  const table = document.createElement('table');
  table.className = 'data';
  const head = document.createElement('tr');
  for (const c of t.columns) {
    const th = document.createElement('th');
    th.textContent = c;
    head.append(th);
  }
  const thead = document.createElement('thead');
  thead.append(head);
  const body = document.createElement('tbody');
  for (const r of t.rows) {
    const tr = document.createElement('tr');
    for (const cell of r) {
      const td = document.createElement('td');
      td.textContent = cell == null ? 'null' : utcText(cell); // timestamps as every page shows time; the CSV keeps them whole
      tr.append(td);
    }
    body.append(tr);
  }
  table.append(thead, body);
  return table;
}

/** RFC 4180 CSV: every field quoted when it holds a comma, quote or line break. */
export function csv(header, rows) {
  const field = (v) => {
    const s = v == null ? '' : String(v);
    return /[",\r\n]/.test(s) ? `"${s.replaceAll('"', '""')}"` : s;
  };
  return [header, ...rows].map((r) => r.map(field).join(',')).join('\r\n') + '\r\n';
}

/** A link that saves these bytes under this name (a blob: URL, so the CSP needs nothing more). */
export function download(link, name, blob) {
  if (link.href.startsWith('blob:')) URL.revokeObjectURL(link.href);
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.hidden = false;
}
