import { vehicleName } from './names.js';
import { prepareCanvas } from './canvas.js';
// An offline map: latitude/longitude grid lines, each vehicle's whole track in time order with GPS fixes (filled dots)
// told from dead-reckoned ones (open rings), its latest fix and name, a legend and a scale bar. No tiles, no internet.
// Drawn at the canvas's size on screen in CSS pixels (sharp, and the labels as large on a phone as on a desk).
// A vehicle is { name, track: [fix] }, a fix { lat, lon, t, gps } or a [lat, lon] pair (a GPS fix, as the public view
// sends). `layers` are drawn last, each called with (g, { x(lon), y(lat), w, h }): room for currents and waypoints.
// `focus` names the vehicle the map is fitted to (the others still drawn where they fall); none: every vehicle.
// A vehicle's `also` (places, not fixes: its waypoint) are kept in view but not drawn as its track.
// currentLayer and waypointLayer are the call records' layers (docs/surfacings.md#on-the-map); each counts what it drew
// on the canvas (data-arrows, data-waypoints), reset at every drawing, as are plan-layers.js's data-plan-waypoints
// and data-goto. Every label goes through placeLabel, which keeps it off every other label, the legend and the scale:
// the boxes it placed are the canvas's data-labels. A layer with a `legend` ([{ text, mark(g, x, y) }]) adds those
// entries to the legend.

/** A fix in one form: [lat, lon] pairs are GPS fixes. */
export function fix(p) {
  return Array.isArray(p) ? { lat: p[0], lon: p[1], t: 0, gps: true } : p;
}

export function colour(i) {
  return `hsl(${(i * 67) % 360} 70% 38%)`;
}

export function drawMap(canvas, vehicles, layers = [], focus = '') {
  const { g, w, h, ink } = prepareCanvas(canvas, 200, 150, 800, 600);
  const tracks = vehicles.map((v) => ({ name: v.name, fixes: v.track.map(fix) }));
  const points = tracks.flatMap((v) => v.fixes);
  const inView = (v) => [...v.track.map(fix), ...(v.also || [])];
  const mine = vehicles.find((v) => v.name === focus && v.track.length);
  const fitted = mine ? inView(mine) : vehicles.flatMap(inView);

  // Bounds with equal distances across and up (a degree of longitude is cos(lat) of one of latitude).
  let [minLat, maxLat, minLon, maxLon] = [-60, 60, -180, 180];
  if (fitted.length) {
    minLat = Math.min(...fitted.map((p) => p.lat)); maxLat = Math.max(...fitted.map((p) => p.lat));
    minLon = Math.min(...fitted.map((p) => p.lon)); maxLon = Math.max(...fitted.map((p) => p.lon));
  }
  const k = Math.max(0.05, Math.cos((((minLat + maxLat) / 2) * Math.PI) / 180));
  const spanLat = Math.max(0.01, maxLat - minLat) * 1.3, spanLon = Math.max(0.01, maxLon - minLon) * 1.3;
  // The legend and the scale take the map's foot: what is fitted goes above them. The scale bar is at most a third of
  // the width, so the legend laid out in the rest takes at least as many rows as it will beside the real bar.
  const entries = [...LEGEND, ...layers.flatMap((l) => l.legend || [])].filter((e, i, all) => all.findIndex((o) => o.text === e.text) === i);
  const top = h - legendBox(g, entries, h, w * 0.6).h - 10;
  const perDegree = Math.min(top / spanLat, w / (spanLon * k)); // pixels per degree of latitude
  const midLat = (minLat + maxLat) / 2, midLon = (minLon + maxLon) / 2;
  const x = (lon) => w / 2 + (lon - midLon) * k * perDegree;
  const y = (lat) => top / 2 - (lat - midLat) * perDegree;

  // Grid steps by the room each axis has: a label of longitude needs about 110 px, one of latitude 60.
  const latStep = niceStep(h / perDegree / Math.max(2, Math.floor(h / 60)));
  const lonStep = niceStep(w / (k * perDegree) / Math.max(2, Math.floor(w / 110)));
  const digits = (step) => Math.max(0, -Math.floor(Math.log10(step)));
  g.strokeStyle = ink('--line', '#ccc');
  g.fillStyle = ink('--muted', '#555');
  g.font = '13px system-ui, sans-serif';
  g.lineWidth = 1;
  const lat0 = midLat - (h - top / 2) / perDegree, lat1 = midLat + top / 2 / perDegree;
  const lon0 = midLon - w / 2 / (k * perDegree), lon1 = midLon + w / 2 / (k * perDegree);
  const gridLabels = []; // [text, x, baseline]: drawn last, where no other label is
  for (let lat = Math.ceil(lat0 / latStep) * latStep; lat <= lat1; lat += latStep) {
    g.beginPath(); g.moveTo(0, y(lat)); g.lineTo(w, y(lat)); g.stroke();
    if (y(lat) > 30 && y(lat) < h - 30) gridLabels.push([`${lat.toFixed(digits(latStep))}°`, 4, y(lat) - 3]);
  }
  for (let lon = Math.ceil(lon0 / lonStep) * lonStep; lon <= lon1; lon += lonStep) {
    g.beginPath(); g.moveTo(x(lon), 0); g.lineTo(x(lon), h); g.stroke();
    const text = `${lon.toFixed(digits(lonStep))}°`;
    if (x(lon) + 3 + g.measureText(text).width < w - 2) gridLabels.push([text, x(lon) + 3, 14]);
  }

  // The legend and the scale first: labels keep off them.
  const scale = scaleBox(g, w, h, perDegree);
  const key = legendBox(g, entries, h, scale.x - 10);
  const placed = [{ x: scale.x, y: scale.y, w: scale.w, h: scale.h, text: 'scale' }, { x: key.x, y: key.y, w: key.w, h: key.h, text: 'legend' }];
  let gps = 0, dr = 0;
  tracks.forEach((v, i) => {
    if (!v.fixes.length) return;
    const c = colour(i);
    const fixes = [...v.fixes].sort((a, b) => (a.t || 0) - (b.t || 0));
    g.strokeStyle = c; g.fillStyle = c;
    // One line through the GPS fixes, a thinner dashed one through the dead-reckoned positions: the two disagree by
    // the glider's drift, and one line through both would zig-zag between them.
    for (const gpsOnes of [false, true]) {
      g.lineWidth = gpsOnes ? 2 : 1;
      g.setLineDash(gpsOnes ? [] : [4, 3]);
      g.beginPath();
      fixes.filter((p) => !!p.gps === gpsOnes).forEach((p, n) => (n ? g.lineTo(x(p.lon), y(p.lat)) : g.moveTo(x(p.lon), y(p.lat))));
      g.stroke();
    }
    g.setLineDash([]);
    g.lineWidth = 1.5;
    for (const p of fixes) {
      g.beginPath();
      if (p.gps) { gps++; g.arc(x(p.lon), y(p.lat), 3.5, 0, 2 * Math.PI); g.fill(); } else { dr++; g.arc(x(p.lon), y(p.lat), 2.5, 0, 2 * Math.PI); g.stroke(); }
    }
    const last = fixes[fixes.length - 1];
    g.beginPath(); g.arc(x(last.lon), y(last.lat), 7, 0, 2 * Math.PI); g.fill();
    // a vehicle's name must show: when every place near its fix is taken it goes further up or down
    placeLabel(g, vehicleName(v.name), x(last.lon), y(last.lat), { w, h, placed }, { colour: c, size: 15, bold: true, gap: 10, must: true });
  });
  canvas.dataset.arrows = '0';
  canvas.dataset.waypoints = '0';
  canvas.dataset.planWaypoints = '0';
  canvas.dataset.goto = '[]';
  layers.forEach((layer) => layer(g, { x, y, w, h, placed }));
  // the grid's degrees matter least: each only where no name, number or waypoint text is
  g.font = '13px system-ui, sans-serif';
  g.fillStyle = ink('--muted', '#555');
  for (const [text, gx, base] of gridLabels) {
    const b = { x: gx, y: base - 13, w: g.measureText(text).width, h: 16 };
    if (!placed.some((o) => b.x < o.x + o.w && o.x < b.x + b.w && b.y < o.y + o.h && o.y < b.y + b.h)) g.fillText(text, gx, base);
  }
  drawLegend(g, entries, key, ink);
  drawScale(g, scale, ink);
  canvas.dataset.points = String(points.length);
  canvas.dataset.gps = String(gps);
  canvas.dataset.dr = String(dr);
  canvas.dataset.labels = JSON.stringify(placed.map((b) => [b.text, Math.round(b.x), Math.round(b.y), Math.round(b.w), Math.round(b.h)]));
}

/**
 * A label near (px, py) where it covers no box in `room.placed` and stays inside the map: right of the point and above
 * it, else below, else left; with `must`, further up and down the right side, and at last where it first wanted to be.
 * Drawn with a halo in `style.colour`; its box is added to `room.placed` and returned (null when not drawn).
 */
export function placeLabel(g, text, px, py, room, style = {}) {
  const { colour: c = '#222', size = 12, bold = true, gap = 9, must = false } = style;
  g.save();
  g.font = `${bold ? 'bold ' : ''}${size}px system-ui, sans-serif`;
  const tw = g.measureText(text).width;
  const lh = size + 3;
  const above = py - gap + 2, below = py + gap + size - 2; // baselines
  const spots = [[px + gap, above], [px + gap, below], [px - gap - tw, above], [px - gap - tw, below]];
  if (must) for (let k = 1; k <= 8; k++) spots.push([px + gap, above - k * lh], [px + gap, below + k * lh]);
  const box = ([bx, base]) => ({ x: Math.max(2, Math.min(bx, room.w - tw - 2)), y: base - size, w: tw, h: lh, text });
  const free = (b) => b.y >= 0 && b.y + b.h <= room.h && !room.placed.some((o) => b.x < o.x + o.w && o.x < b.x + b.w && b.y < o.y + o.h && o.y < b.y + b.h);
  let at = spots.map(box).find(free);
  if (!at && must) {
    at = box(spots[0]);
    at.y = Math.max(0, Math.min(at.y, room.h - lh));
  }
  if (at) {
    room.placed.push(at);
    g.lineWidth = 3; g.strokeStyle = getComputedStyle(document.documentElement).getPropertyValue('--card').trim() || '#fff';
    g.lineJoin = 'round';
    g.strokeText(text, at.x, at.y + size);
    g.fillStyle = c; g.fillText(text, at.x, at.y + size);
  }
  g.restore();
  return at || null;
}

/** Pixels a current of 1 m/s is drawn long (a typical 0.1 m/s: 18 px). */
export const ARROW_PX_PER_MPS = 180;

/**
 * A layer: the depth-averaged current at each surfacing as an arrow from where the glider surfaced, pointing where the
 * water goes. `points` are { lat, lon, current_e, current_n } (m/s east and north), as ?surfacings --outlook's track has them.
 */
export function currentLayer(points, c = '#0b5cad') {
  return (g, { x, y }) => {
    let n = 0;
    g.save();
    g.strokeStyle = c; g.fillStyle = c; g.lineWidth = 2;
    for (const p of points) {
      if (p.current_e == null || p.current_n == null || p.lat == null) continue;
      const x0 = x(p.lon), y0 = y(p.lat);
      let dx = p.current_e * ARROW_PX_PER_MPS, dy = -p.current_n * ARROW_PX_PER_MPS;
      const len = Math.hypot(dx, dy);
      if (len < 1e-9) continue;
      const shown = Math.min(80, Math.max(10, len)); // a whisper of current still shows its way; a flood stays on the map
      dx *= shown / len; dy *= shown / len;
      g.beginPath(); g.moveTo(x0, y0); g.lineTo(x0 + dx, y0 + dy); g.stroke();
      const a = Math.atan2(dy, dx);
      g.beginPath();
      g.moveTo(x0 + dx, y0 + dy);
      g.lineTo(x0 + dx - 7 * Math.cos(a - 0.45), y0 + dy - 7 * Math.sin(a - 0.45));
      g.lineTo(x0 + dx - 7 * Math.cos(a + 0.45), y0 + dy - 7 * Math.sin(a + 0.45));
      g.closePath(); g.fill();
      n++;
    }
    g.restore();
    g.canvas.dataset.arrows = String(Number(g.canvas.dataset.arrows || 0) + n);
  };
}

/**
 * A layer: the waypoint the glider steers for (c_wpt_lat/lon) as a crossed square, and a dashed line to it from the
 * last fix, labelled with what `words` says (distance, bearing, ETA). `from`, `to`: { lat, lon }.
 */
export function waypointLayer(from, to, words = '', c = '#9a6700') {
  return (g, { x, y, w, h, placed }) => {
    if (!to || to.lat == null) return;
    const tx = x(to.lon), ty = y(to.lat);
    g.save();
    g.strokeStyle = c; g.lineWidth = 2;
    if (from && from.lat != null) {
      g.setLineDash([6, 4]);
      g.beginPath(); g.moveTo(x(from.lon), y(from.lat)); g.lineTo(tx, ty); g.stroke();
      g.setLineDash([]);
    }
    g.strokeRect(tx - 6, ty - 6, 12, 12);
    g.beginPath(); g.moveTo(tx - 6, ty - 6); g.lineTo(tx + 6, ty + 6); g.moveTo(tx + 6, ty - 6); g.lineTo(tx - 6, ty + 6); g.stroke();
    g.restore();
    if (words) placeLabel(g, words, tx, ty, { w, h, placed }, { colour: c, size: 13, bold: false, gap: 10, must: true });
    g.canvas.dataset.waypoints = String(Number(g.canvas.dataset.waypoints || 0) + 1);
  };
}

/** What every map's legend says. */
const LEGEND = [
  { text: 'GPS', mark: (g, x, y) => { g.beginPath(); g.arc(x + 5, y, 3.5, 0, 2 * Math.PI); g.fill(); } },
  { text: 'dead-reckoned', mark: (g, x, y) => { g.beginPath(); g.arc(x + 5, y, 2.5, 0, 2 * Math.PI); g.stroke(); } },
];

/** Where the legend's entries go at the map's foot: in rows no wider than `room`, from the left. */
function legendBox(g, entries, h, room) {
  g.font = '13px system-ui, sans-serif';
  const rows = [[]];
  let used = 0;
  for (const e of entries) {
    const ew = 16 + g.measureText(e.text).width + 12;
    if (used + ew > Math.max(room - 8, 80) && rows[rows.length - 1].length) { rows.push([]); used = 0; }
    rows[rows.length - 1].push({ e, dx: used });
    used += ew;
  }
  const width = Math.max(...rows.map((r) => r.reduce((m, { e, dx }) => Math.max(m, dx + 16 + g.measureText(e.text).width), 0)));
  const bh = rows.length * 18 + 4;
  return { x: 4, y: h - 6 - bh, w: width + 12, h: bh, rows };
}

function drawLegend(g, entries, box, ink) {
  g.save();
  g.font = '13px system-ui, sans-serif';
  g.fillStyle = ink('--card', '#fff'); g.globalAlpha = 0.85; g.fillRect(box.x, box.y, box.w, box.h); g.globalAlpha = 1;
  box.rows.forEach((row, r) => {
    const base = box.y + 16 + r * 18;
    for (const { e, dx } of row) {
      g.fillStyle = ink('--fg', '#222'); g.strokeStyle = ink('--fg', '#222'); g.lineWidth = 1.5;
      g.save(); e.mark(g, box.x + 6 + dx, base - 4); g.restore();
      g.fillStyle = ink('--fg', '#222');
      g.fillText(e.text, box.x + 6 + dx + 16, base);
    }
  });
  g.restore();
  g.canvas.dataset.legend = entries.map((e) => e.text).join(', ');
}

/** A bar of a round distance, about a quarter of the map wide: where it goes. */
function scaleBox(g, w, h, perDegree) {
  const metresPerPixel = 111320 / perDegree;
  const metres = niceStep(metresPerPixel * w * 0.22);
  const px = metres / metresPerPixel;
  const text = metres >= 1000 ? `${metres / 1000} km` : `${metres} m`;
  const x1 = w - 12, x0 = x1 - px, y = h - 12;
  return { x: x0 - 6, y: y - 22, w: px + 12, h: 28, x0, x1, base: y, px, text };
}

function drawScale(g, s, ink) {
  g.save();
  g.fillStyle = ink('--card', '#fff'); g.globalAlpha = 0.85; g.fillRect(s.x, s.y, s.w, s.h); g.globalAlpha = 1;
  g.strokeStyle = ink('--fg', '#222'); g.lineWidth = 2;
  g.beginPath(); g.moveTo(s.x0, s.base - 6); g.lineTo(s.x0, s.base); g.lineTo(s.x1, s.base); g.lineTo(s.x1, s.base - 6); g.stroke();
  g.fillStyle = ink('--fg', '#222'); g.font = '13px system-ui, sans-serif';
  g.fillText(s.text, s.x0 + (s.px - g.measureText(s.text).width) / 2, s.base - 8);
  g.restore();
  g.canvas.dataset.scale = s.text;
}

function niceStep(raw) {
  const p = Math.pow(10, Math.floor(Math.log10(raw || 1)));
  const n = raw / p;
  return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * p;
}
