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
// on the canvas (data-arrows, data-waypoints), reset at every drawing.

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
  const perDegree = Math.min(h / spanLat, w / (spanLon * k)); // pixels per degree of latitude
  const midLat = (minLat + maxLat) / 2, midLon = (minLon + maxLon) / 2;
  const x = (lon) => w / 2 + (lon - midLon) * k * perDegree;
  const y = (lat) => h / 2 - (lat - midLat) * perDegree;

  // Grid steps by the room each axis has: a label of longitude needs about 110 px, one of latitude 60.
  const latStep = niceStep(h / perDegree / Math.max(2, Math.floor(h / 60)));
  const lonStep = niceStep(w / (k * perDegree) / Math.max(2, Math.floor(w / 110)));
  const digits = (step) => Math.max(0, -Math.floor(Math.log10(step)));
  g.strokeStyle = ink('--line', '#ccc');
  g.fillStyle = ink('--muted', '#555');
  g.font = '13px system-ui, sans-serif';
  g.lineWidth = 1;
  const lat0 = midLat - h / 2 / perDegree, lat1 = midLat + h / 2 / perDegree;
  const lon0 = midLon - w / 2 / (k * perDegree), lon1 = midLon + w / 2 / (k * perDegree);
  for (let lat = Math.ceil(lat0 / latStep) * latStep; lat <= lat1; lat += latStep) {
    g.beginPath(); g.moveTo(0, y(lat)); g.lineTo(w, y(lat)); g.stroke();
    if (y(lat) > 30 && y(lat) < h - 30) g.fillText(`${lat.toFixed(digits(latStep))}°`, 4, y(lat) - 3);
  }
  for (let lon = Math.ceil(lon0 / lonStep) * lonStep; lon <= lon1; lon += lonStep) {
    g.beginPath(); g.moveTo(x(lon), 0); g.lineTo(x(lon), h); g.stroke();
    const text = `${lon.toFixed(digits(lonStep))}°`;
    if (x(lon) + 3 + g.measureText(text).width < w - 2) g.fillText(text, x(lon) + 3, 14);
  }

  let gps = 0, dr = 0;
  const placed = []; // label boxes so far: a name never covers another
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
    label(g, vehicleName(v.name), x(last.lon) + 10, y(last.lat) - 8, w, ink('--card', '#fff'), c, placed);
  });
  canvas.dataset.arrows = '0';
  canvas.dataset.waypoints = '0';
  layers.forEach((layer) => layer(g, { x, y, w, h }));
  legend(g, h, ink);
  scaleBar(g, w, h, perDegree, ink);
  canvas.dataset.points = String(points.length);
  canvas.dataset.gps = String(gps);
  canvas.dataset.dr = String(dr);
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
  return (g, { x, y, w }) => {
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
    if (words) {
      g.font = '13px system-ui, sans-serif';
      const tw = g.measureText(words).width;
      const at = Math.max(4, Math.min(tx + 10, w - tw - 4));
      g.lineWidth = 4; g.strokeStyle = '#fff'; g.strokeText(words, at, ty + 18);
      g.fillStyle = c; g.fillText(words, at, ty + 18);
    }
    g.restore();
    g.canvas.dataset.waypoints = String(Number(g.canvas.dataset.waypoints || 0) + 1);
  };
}

/** A name with a halo, kept inside the map and below any name it would cover. */
function label(g, text, px, py, w, halo, c, placed) {
  g.font = 'bold 15px system-ui, sans-serif';
  const tw = g.measureText(text).width;
  const at = Math.min(px, w - tw - 4);
  let top = Math.max(18, py);
  while (placed.some((b) => at < b.x + b.w && b.x < at + tw && Math.abs(top - b.y) < 18)) top += 18;
  placed.push({ x: at, y: top, w: tw });
  g.lineWidth = 4; g.strokeStyle = halo; g.strokeText(text, at, top);
  g.fillStyle = c; g.fillText(text, at, top);
}

function legend(g, h, ink) {
  g.font = '13px system-ui, sans-serif';
  const y = h - 12;
  g.fillStyle = ink('--card', '#fff'); g.globalAlpha = 0.85; g.fillRect(4, y - 14, 190, 20); g.globalAlpha = 1;
  g.fillStyle = ink('--fg', '#222'); g.strokeStyle = ink('--fg', '#222'); g.lineWidth = 1.5;
  g.beginPath(); g.arc(14, y - 4, 3.5, 0, 2 * Math.PI); g.fill();
  g.fillText('GPS', 22, y);
  g.beginPath(); g.arc(64, y - 4, 2.5, 0, 2 * Math.PI); g.stroke();
  g.fillText('dead-reckoned', 72, y);
}

/** A bar of a round distance, about a quarter of the map wide. */
function scaleBar(g, w, h, perDegree, ink) {
  const metresPerPixel = 111320 / perDegree;
  const metres = niceStep(metresPerPixel * w * 0.22);
  const px = metres / metresPerPixel;
  const text = metres >= 1000 ? `${metres / 1000} km` : `${metres} m`;
  const x1 = w - 12, x0 = x1 - px, y = h - 12;
  g.fillStyle = ink('--card', '#fff'); g.globalAlpha = 0.85; g.fillRect(x0 - 6, y - 22, px + 12, 28); g.globalAlpha = 1;
  g.strokeStyle = ink('--fg', '#222'); g.lineWidth = 2;
  g.beginPath(); g.moveTo(x0, y - 6); g.lineTo(x0, y); g.lineTo(x1, y); g.lineTo(x1, y - 6); g.stroke();
  g.fillStyle = ink('--fg', '#222'); g.font = '13px system-ui, sans-serif';
  g.fillText(text, x0 + (px - g.measureText(text).width) / 2, y - 8);
  g.canvas.dataset.scale = text;
}

function niceStep(raw) {
  const p = Math.pow(10, Math.floor(Math.log10(raw || 1)));
  const n = raw / p;
  return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * p;
}
