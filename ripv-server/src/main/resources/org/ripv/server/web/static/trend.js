// A small trend chart on a canvas: one series across calls (time along, value up), its last value in the title, the
// range on the axes, every call a dot. Drawn at the canvas's size on screen in CSS pixels, as the map is.
import { clock, day } from './time.js';
import { prepareCanvas } from './canvas.js';

/**
 * Draws `values` (numbers or null, one per time in `times`, epoch ms) into canvas. Sets data-points to the number of
 * values drawn; a series with none says so instead of drawing a line.
 */
export function drawTrend(canvas, times, values, title, unit, c = '#0b5cad') {
  const { g, w, h, ink } = prepareCanvas(canvas, 160, 100, 320, 160);
  const pts = times.map((t, i) => [t, values[i]]).filter(([t, v]) => t != null && v != null && Number.isFinite(v));
  g.font = '600 13px system-ui, sans-serif';
  g.fillStyle = ink('--fg', '#222');
  const last = pts.length ? pts[pts.length - 1][1] : null;
  g.fillText(`${title}${last == null ? '' : `: ${Number(last.toPrecision(4))} ${unit}`}`, 6, 15);
  canvas.dataset.points = String(pts.length);
  canvas.setAttribute('aria-label', `${title} across calls: ${pts.length ? `${pts.length} values, last ${last} ${unit}` : 'none'}`);
  g.font = '12px system-ui, sans-serif';
  g.fillStyle = ink('--muted', '#555');
  if (!pts.length) { g.fillText('not in these calls', 6, h / 2 + 4); return; }
  const t0 = pts[0][0], t1 = pts[pts.length - 1][0];
  let lo = Math.min(...pts.map((p) => p[1])), hi = Math.max(...pts.map((p) => p[1]));
  if (hi - lo < 1e-9) { const pad = Math.abs(hi) * 0.05 || 0.5; lo -= pad; hi += pad; }
  const left = 52, right = w - 8, top = 24, bottom = h - 22;
  const x = (t) => (t1 === t0 ? (left + right) / 2 : left + ((t - t0) / (t1 - t0)) * (right - left));
  const y = (v) => bottom - ((v - lo) / (hi - lo)) * (bottom - top);
  g.strokeStyle = ink('--line', '#ccc'); g.lineWidth = 1;
  g.beginPath(); g.moveTo(left, top); g.lineTo(left, bottom); g.lineTo(right, bottom); g.stroke();
  const label = (v) => String(Number(v.toPrecision(4)));
  g.fillText(label(hi), 4, top + 4);
  g.fillText(label(lo), 4, bottom);
  const cut = t1 - t0 < 600000 ? 8 : 5; // seconds only when the calls are minutes apart
  g.fillText(clock(t0).slice(0, cut), left, h - 6);
  const end = day(t1) === day(t0) ? clock(t1).slice(0, cut) : `${day(t1).slice(5)} ${clock(t1).slice(0, 5)}`;
  g.fillText(end, right - g.measureText(end).width, h - 6);
  g.strokeStyle = c; g.fillStyle = c; g.lineWidth = 2;
  g.beginPath();
  pts.forEach(([t, v], i) => (i ? g.lineTo(x(t), y(v)) : g.moveTo(x(t), y(v))));
  g.stroke();
  for (const [t, v] of pts) { g.beginPath(); g.arc(x(t), y(v), 2.5, 0, 2 * Math.PI); g.fill(); }
}
