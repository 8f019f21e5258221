// The map on the operator's tiles (--map-tiles URL) with Leaflet from the server's WebJar: each
// vehicle's whole track (GPS fixes filled, dead-reckoned ones as rings, as on the offline map), its latest fix, a scale,
// and as on the offline map the depth-averaged current at each surfacing (v.currents) and the waypoint with the line to it
// (v.waypoint). The CSP lets images come from that tile host only.
import * as L from '/webjars/leaflet/1.9.4/dist/leaflet-src.esm.js';
import { vehicleName } from './names.js';
import { fix, colour, ARROW_PX_PER_MPS } from './map.js';

export function tileMap(canvas, template) {
  const css = document.createElement('link');
  css.rel = 'stylesheet';
  css.href = '/webjars/leaflet/1.9.4/dist/leaflet.css';
  document.head.append(css);
  const div = document.createElement('div');
  div.id = canvas.id;
  div.className = 'tiles';
  div.setAttribute('role', 'img');
  div.setAttribute('aria-label', canvas.getAttribute('aria-label') || 'Map');
  canvas.replaceWith(div);
  const map = L.map(div, { worldCopyJump: true, preferCanvas: true }).setView([0, 0], 2);
  const host = new URL(template.replaceAll(/\{[a-z]\}/g, '0')).host;
  L.tileLayer(template, { maxZoom: 18, attribution: `Tiles: ${host}` }).addTo(map);
  L.control.scale({ imperial: false }).addTo(map);
  const layer = L.layerGroup().addTo(map);
  let fitted = null; // the focus the map was last fitted to
  let last = null; // what was drawn: arrows are sized in pixels, so a zoom draws them again
  map.on('zoomend', () => { if (last) draw(...last); });
  const draw = (vehicles, focus = '') => {
    last = [vehicles, focus];
    layer.clearLayers();
    const all = [];
    let arrows = 0;
    let waypoints = 0;
    vehicles.forEach((v, i) => {
      if (!v.track.length) return;
      const c = colour(i);
      const fixes = v.track.map(fix).sort((a, b) => (a.t || 0) - (b.t || 0));
      const points = fixes.map((p) => [p.lat, p.lon]);
      // GPS fixes joined by a solid line, dead-reckoned positions by a dashed one (they differ by the drift).
      L.polyline(fixes.filter((p) => p.gps).map((p) => [p.lat, p.lon]), { color: c, weight: 2 }).addTo(layer);
      L.polyline(fixes.filter((p) => !p.gps).map((p) => [p.lat, p.lon]), { color: c, weight: 1, dashArray: '4 3' }).addTo(layer);
      for (const p of fixes) {
        L.circleMarker([p.lat, p.lon], p.gps ? { radius: 3.5, color: c, fillOpacity: 1, weight: 1 } : { radius: 2.5, color: c, fill: false, weight: 1.5 }).addTo(layer);
      }
      const last = points[points.length - 1];
      for (const p of v.currents || []) arrows += arrow(map, layer, p, c);
      const w = v.waypoint;
      if (w?.to) {
        if (w.from) L.polyline([[w.from.lat, w.from.lon], [w.to.lat, w.to.lon]], { color: c, weight: 1.5, dashArray: '6 4' }).addTo(layer);
        L.circleMarker([w.to.lat, w.to.lon], { radius: 6, color: c, fill: false, weight: 2 })
          .bindTooltip(label(w.words ? `waypoint ${w.words}` : 'waypoint')).addTo(layer);
        waypoints++;
      }
      const newest = points[points.length - 1];
      L.circleMarker(newest, { radius: 7, color: c, fillOpacity: 0.9 }).bindTooltip(label(vehicleName(v.name)), { permanent: true }).addTo(layer);
      all.push(...points);
    });
    const mine = vehicles.find((v) => v.name === focus && v.track.length);
    const bounds = mine ? mine.track.map(fix).map((p) => [p.lat, p.lon]) : all;
    if (bounds.length && fitted !== focus) { map.fitBounds(bounds, { maxZoom: 12, padding: [20, 20] }); fitted = focus; }
    div.dataset.points = String(all.length);
    div.dataset.arrows = String(arrows);
    div.dataset.waypoints = String(waypoints);
  };
  return draw;
}

/** The current at a surfacing as an arrow of the offline map's length in pixels (1 if drawn). */
function arrow(map, layer, p, c) {
  if (p.current_e == null || p.current_n == null || p.lat == null) return 0;
  let dx = p.current_e * ARROW_PX_PER_MPS, dy = -p.current_n * ARROW_PX_PER_MPS;
  const len = Math.hypot(dx, dy);
  if (len < 1e-9) return 0;
  const shown = Math.min(80, Math.max(10, len));
  dx *= shown / len; dy *= shown / len;
  const at = (x, y) => map.layerPointToLatLng(L.point(x, y));
  const o = map.latLngToLayerPoint([p.lat, p.lon]);
  const tip = L.point(o.x + dx, o.y + dy);
  const a = Math.atan2(dy, dx);
  L.polyline([at(o.x, o.y), at(tip.x, tip.y)], { color: c, weight: 2 }).addTo(layer);
  L.polygon([at(tip.x, tip.y), at(tip.x - 7 * Math.cos(a - 0.45), tip.y - 7 * Math.sin(a - 0.45)),
    at(tip.x - 7 * Math.cos(a + 0.45), tip.y - 7 * Math.sin(a + 0.45))], { color: c, weight: 1, fillOpacity: 1 }).addTo(layer);
  return 1;
}

// Leaflet sets a string tooltip as HTML; a vehicle's name goes in as text.
function label(text) {
  const span = document.createElement('span');
  span.textContent = text;
  return span;
}
